package io.rtaware.zenoh;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.Locale;

/**
 * Loads the native Zenoh layer once per JVM (a native library can be loaded only once per
 * class loader, so this is process state by nature) and tells whether it is there. The library
 * is taken from the system property {@code rtaware.zenoh.library} (a file) when set, otherwise
 * from the class path ({@code native/<os>-<arch>/}, where the Maven build puts it when cargo is
 * present), copied to a temporary file first. Thread-safe.
 */
public final class ZenohLibrary {

    /** What a user does to get the native layer, for messages that say it is missing. */
    public static final String HOW_TO_ENABLE = "install Rust 1.75 or newer (cargo on the PATH) and rebuild "
            + "(./mvnw -B -DskipTests package, or delete rtaware-app/target and run ./rtaware again)";

    private static final Object LOCK = new Object();
    private static String failure;
    private static boolean attempted;

    private ZenohLibrary() {
    }

    /** @return whether the native Zenoh layer is loaded (loading it on the first call) */
    public static boolean isAvailable() {
        return unavailableReason() == null;
    }

    /**
     * @return null when the native layer is loaded, otherwise one sentence saying why it is not
     *     and how to enable it
     */
    public static String unavailableReason() {
        synchronized (LOCK) {
            if (!attempted) {
                attempted = true;
                failure = load();
            }
            return failure;
        }
    }

    /**
     * @throws ZenohException if the native layer is not available, with the reason
     */
    public static void require() throws ZenohException {
        String reason = unavailableReason();
        if (reason != null) {
            throw new ZenohException(reason);
        }
    }

    private static String load() {
        String explicit = System.getProperty("rtaware.zenoh.library");
        try {
            if (explicit != null && !explicit.isBlank()) {
                System.load(Path.of(explicit).toAbsolutePath().toString());
                return null;
            }
            Path file = extract(System.mapLibraryName("rtaware_zenoh"));
            if (file == null) {
                return "the native Zenoh layer was not built (no Rust toolchain when the project was built): "
                        + HOW_TO_ENABLE;
            }
            System.load(file.toString());
            return null;
        } catch (IOException | UnsatisfiedLinkError | SecurityException e) {
            return "the native Zenoh layer cannot be loaded (" + e.getMessage() + "): " + HOW_TO_ENABLE;
        }
    }

    /**
     * Copies a file the build put beside the library ({@code native/<os>-<arch>/<name>} on the class
     * path) to a temporary file, deleted when the JVM exits.
     *
     * @param name the file's name
     * @return the copy, or null when the build did not make that file
     * @throws IOException if it cannot be copied
     */
    static Path extract(String name) throws IOException {
        try (InputStream in = ZenohLibrary.class.getResourceAsStream("/native/" + platform() + "/" + name)) {
            if (in == null) {
                return null;
            }
            Path file = Files.createTempFile(name, ".tmp");
            file.toFile().deleteOnExit();
            Files.copy(in, file, StandardCopyOption.REPLACE_EXISTING);
            return file;
        }
    }

    private static String platform() {
        String os = System.getProperty("os.name").toLowerCase(Locale.ROOT);
        String arch = System.getProperty("os.arch").toLowerCase(Locale.ROOT);
        String osName = os.contains("mac") ? "macos" : os.contains("win") ? "windows" : "linux";
        String archName = arch.equals("amd64") || arch.equals("x86_64") ? "x86_64"
                : arch.equals("aarch64") || arch.equals("arm64") ? "aarch64" : arch;
        return osName + "-" + archName;
    }
}
