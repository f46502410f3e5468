package io.rtaware.core.monitor;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.io.InputStream;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.objectweb.asm.ClassReader;
import org.objectweb.asm.ClassVisitor;
import org.objectweb.asm.Handle;
import org.objectweb.asm.MethodVisitor;
import org.objectweb.asm.Opcodes;

/**
 * The classes whose code runs every release load string constants only while they are built and
 * started (class initialization, constructors, the executors' {@code prepare} and {@code start},
 * all before the first release): HotSpot resolves every string constant of a class not
 * resolved yet before it compiles one of the class's methods with C2, on the thread that asked
 * for the compile, so a message on a path no cycle took would be allocated on a worker or task
 * thread in steady state (see {@link OffPathText}, where such text lives).
 */
class ReleasePathConstantsTest {

    /** The methods that run before the first release. */
    private static final Set<String> BUILDING = Set.of("<init>", "<clinit>", "prepare", "start");

    @ParameterizedTest
    @ValueSource(classes = {TaskRuntime.class, CycleToken.class, ReleaseGrid.class, CycleStatistics.class,
            StatisticsTable.class, StatisticsRecorder.class, PooledExecutor.class, ThreadedExecutor.class,
            Watchdog.class, ListenerFanOut.class, TaskHeap.class, ParkingClockWaiter.class, InputHandle.class,
            OutputHandle.class, AdaptivePeriodController.class, Executor.class})
    void stringConstantsAreLoadedOnlyWhileBuilding(Class<?> type) throws IOException {
        List<String> offBuild = new ArrayList<>();
        for (Class<?> each : withNested(type)) {
            offBuild.addAll(stringsLoadedOutsideBuilding(each));
        }
        assertEquals(List.of(), offBuild, type.getSimpleName() + ": string constants outside construction");
    }

    private static List<Class<?>> withNested(Class<?> type) {
        List<Class<?>> all = new ArrayList<>(List.of(type));
        for (Class<?> nested : type.getDeclaredClasses()) {
            all.addAll(withNested(nested));
        }
        return all;
    }

    /** @return "method: constant" for each string loaded by an ldc or bootstrap argument outside construction */
    private static List<String> stringsLoadedOutsideBuilding(Class<?> type) throws IOException {
        List<String> found = new ArrayList<>();
        try (InputStream in = type.getResourceAsStream("/" + type.getName().replace('.', '/') + ".class")) {
            ClassReader reader = new ClassReader(in.readAllBytes());
            reader.accept(new ClassVisitor(Opcodes.ASM9) {
                @Override
                public MethodVisitor visitMethod(int access, String name, String descriptor, String signature,
                                                 String[] exceptions) {
                    boolean building = BUILDING.contains(name);
                    return building ? null : new MethodVisitor(Opcodes.ASM9) {
                        @Override
                        public void visitLdcInsn(Object value) {
                            if (value instanceof String s) {
                                found.add(type.getSimpleName() + "." + name + ": " + s);
                            }
                        }

                        @Override
                        public void visitInvokeDynamicInsn(String indyName, String indyDescriptor, Handle bootstrap,
                                                           Object... arguments) {
                            for (Object argument : arguments) {
                                if (argument instanceof String s) {
                                    found.add(type.getSimpleName() + "." + name + ": " + s);
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
