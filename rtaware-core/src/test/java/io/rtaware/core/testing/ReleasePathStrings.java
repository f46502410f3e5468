package io.rtaware.core.testing;

import java.io.IOException;
import java.io.InputStream;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import org.objectweb.asm.ClassReader;
import org.objectweb.asm.ClassVisitor;
import org.objectweb.asm.Handle;
import org.objectweb.asm.Label;
import org.objectweb.asm.MethodVisitor;
import org.objectweb.asm.Opcodes;

/**
 * Finds the string constants of a release-path class that may still be unresolved once it is
 * built: HotSpot resolves every string constant of a class not resolved yet before it compiles
 * one of the class's methods with C2, on the thread that asked for the compile, so a message on a
 * path no cycle took is allocated on a worker or task thread in steady state (found with the JVMTI
 * probe of {@code scripts/alloc-probe.c}; docs/performance.md). A constant is resolved when the
 * code that loads it first runs; this reads the class files (ASM) and names each string loaded
 * outside the methods that run before the first release, and each loaded inside them on a path
 * that ends in a throw (an argument check's message, built only when the check fails).
 *
 * <p>For the release-path tests of every module ({@code ReleasePathConstantsTest} in core,
 * {@code ClockNanosleepTest} in the real-time layer, {@code ReleaseStatsTest} in the bench); ASM is
 * a test dependency of each.
 */
public final class ReleasePathStrings {

    /** The methods that run before the first release: class and object initialization, an executor's prepare and start. */
    private static final Set<String> BUILDING = Set.of("<init>", "<clinit>", "prepare", "start");

    private ReleasePathStrings() {
    }

    /**
     * @param type a class whose code runs on the release path
     * @return "Class.method: constant" for each string constant of it or its nested classes that
     *     may be unresolved after construction; empty when there is none
     * @throws IOException if its class file cannot be read
     */
    public static List<String> unresolvedAfterBuilding(Class<?> type) throws IOException {
        List<String> found = new ArrayList<>();
        for (Class<?> each : withNested(type)) {
            found.addAll(stringsLoadedOutsideBuilding(each));
        }
        return found;
    }

    /**
     * @return the class and its nested classes, but for those named {@code CheckText}: a class
     *     that holds the text of its outer class's argument checks in a constant pool of its own
     *     (each class has its own; a C2 compile resolves only its method's class's constants)
     */
    private static List<Class<?>> withNested(Class<?> type) {
        List<Class<?>> all = new ArrayList<>(List.of(type));
        for (Class<?> nested : type.getDeclaredClasses()) {
            if (!nested.getSimpleName().equals("CheckText")) {
                all.addAll(withNested(nested));
            }
        }
        return all;
    }

    /**
     * @return "method: constant" for each string loaded by an ldc or bootstrap argument outside
     *     construction, or inside it on a path that ends in a throw (an argument check whose
     *     message is built only when it fails stays unresolved after construction): a string
     *     loaded between a jump target and an {@code athrow} with no jump target between them
     */
    private static List<String> stringsLoadedOutsideBuilding(Class<?> type) throws IOException {
        List<String> found = new ArrayList<>();
        try (InputStream in = type.getResourceAsStream("/" + type.getName().replace('.', '/') + ".class")) {
            ClassReader reader = new ClassReader(in.readAllBytes());
            reader.accept(new ClassVisitor(Opcodes.ASM9) {
                @Override
                public MethodVisitor visitMethod(int access, String name, String descriptor, String signature,
                                                 String[] exceptions) {
                    boolean building = BUILDING.contains(name);
                    return new MethodVisitor(Opcodes.ASM9) {
                        /** The strings loaded since the last jump target, in a building method. */
                        private final List<String> sinceLabel = new ArrayList<>();

                        private void loaded(String s) {
                            if (building) {
                                sinceLabel.add(s);
                            } else {
                                found.add(type.getSimpleName() + "." + name + ": " + s);
                            }
                        }

                        @Override
                        public void visitLabel(Label label) {
                            sinceLabel.clear();
                        }

                        @Override
                        public void visitInsn(int opcode) {
                            if (opcode == Opcodes.ATHROW) {
                                for (String s : sinceLabel) {
                                    found.add(type.getSimpleName() + "." + name + " (on a throw): " + s);
                                }
                                sinceLabel.clear();
                            }
                        }

                        @Override
                        public void visitLdcInsn(Object value) {
                            if (value instanceof String s) {
                                loaded(s);
                            }
                        }

                        @Override
                        public void visitInvokeDynamicInsn(String indyName, String indyDescriptor, Handle bootstrap,
                                                           Object... arguments) {
                            for (Object argument : arguments) {
                                if (argument instanceof String s) {
                                    loaded(s);
                                }
                            }
                        }
                    };
                }
            }, ClassReader.SKIP_DEBUG);
        }
        return found;
    }
}
