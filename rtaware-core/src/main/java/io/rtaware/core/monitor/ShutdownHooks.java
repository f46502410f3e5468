package io.rtaware.core.monitor;

/**
 * Where {@link Monitor#runUntilStopped(java.io.PrintStream)} installs its shutdown hook: the
 * JVM's ({@link #JVM}), or a test's, which runs the hook itself as the JVM would on Ctrl-C.
 */
interface ShutdownHooks {

    /** The JVM's shutdown hooks ({@link Runtime#addShutdownHook}). */
    ShutdownHooks JVM = new ShutdownHooks() {
        @Override
        public void add(Thread hook) {
            Runtime.getRuntime().addShutdownHook(hook);
        }

        @Override
        public void remove(Thread hook) {
            Runtime.getRuntime().removeShutdownHook(hook);
        }
    };

    /**
     * @param hook a thread not yet started, run when the JVM shuts down
     * @throws IllegalStateException if the JVM is already shutting down
     */
    void add(Thread hook);

    /**
     * @param hook a hook added before
     * @throws IllegalStateException if the JVM is already shutting down
     */
    void remove(Thread hook);
}
