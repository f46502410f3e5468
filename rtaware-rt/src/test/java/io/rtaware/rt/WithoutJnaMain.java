package io.rtaware.rt;

import java.util.Map;

/**
 * Run by {@link WithoutJnaTest} in a JVM whose class path lacks JNA: asks for real-time threads
 * and the absolute sleeper, and prints what it got.
 */
final class WithoutJnaMain {

    private WithoutJnaMain() {
    }

    /**
     * @param args none
     */
    public static void main(String[] args) {
        RealtimeThreads rt = RealtimeThreads.configure(RealtimeThreads.DEFAULT_TOP_PRIORITY, Map.of(), System.err);
        System.out.println("threadSetup=" + rt + " sleeper=" + ClockNanosleep.load().isPresent());
    }
}
