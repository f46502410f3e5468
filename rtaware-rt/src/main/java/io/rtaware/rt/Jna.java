package io.rtaware.rt;

import java.util.Optional;

/**
 * Whether JNA, an optional dependency of this module, is on the class path. Checked before any
 * class that links against JNA is touched, so that its absence costs one line, not a
 * {@link NoClassDefFoundError}. Stateless and thread-safe.
 */
final class Jna {

    private Jna() {
    }

    /** @return why JNA cannot be used, or empty if its classes are present */
    static Optional<String> missingReason() {
        try {
            Class.forName("com.sun.jna.Native", false, Jna.class.getClassLoader());
            return Optional.empty();
        } catch (ClassNotFoundException | LinkageError e) {
            return Optional.of("JNA (net.java.dev.jna:jna) is not on the class path");
        }
    }
}
