package io.rtaware.rt;

import com.sun.jna.Library;
import com.sun.jna.Native;
import com.sun.jna.Platform;

/**
 * {@link LinuxSched} through JNA's mapping of libc. Thread-safe: every call acts on the calling
 * thread ({@code pid 0}) and reads errno right after.
 */
public final class JnaLinuxSched implements LinuxSched {

    private static final int PR_SET_TIMERSLACK = 29;

    /** The libc functions used, as JNA maps them. */
    interface CLib extends Library {
        int sched_setscheduler(int pid, int policy, int[] param);

        int sched_getscheduler(int pid);

        int sched_getparam(int pid, int[] param);

        int sched_setaffinity(int pid, long cpusetsize, long[] mask);

        int prctl(int option, long arg2, long arg3, long arg4, long arg5);
    }

    private final CLib c;

    private JnaLinuxSched(CLib c) {
        this.c = c;
    }

    /**
     * @return the libc binding
     * @throws UnsupportedOperationException if this is not Linux or libc cannot be loaded,
     *     with the reason
     */
    public static JnaLinuxSched load() {
        if (!Platform.isLinux()) {
            throw new UnsupportedOperationException("not Linux (" + System.getProperty("os.name") + ")");
        }
        try {
            return new JnaLinuxSched(Native.load("c", CLib.class));
        } catch (UnsatisfiedLinkError | NoClassDefFoundError e) {
            throw new UnsupportedOperationException("cannot load libc through JNA: " + e.getMessage(), e);
        }
    }

    @Override
    public int setFifo(int priority) {
        return c.sched_setscheduler(0, SCHED_FIFO, new int[] {priority}) == 0 ? 0 : Native.getLastError();
    }

    @Override
    public int scheduler() {
        return c.sched_getscheduler(0);
    }

    @Override
    public int priority() {
        int[] param = new int[1];
        return c.sched_getparam(0, param) == 0 ? param[0] : -1;
    }

    @Override
    public int pinTo(int cpu) {
        long[] mask = new long[cpu / 64 + 1];
        mask[cpu / 64] = 1L << (cpu % 64);
        return c.sched_setaffinity(0, mask.length * 8L, mask) == 0 ? 0 : Native.getLastError();
    }

    @Override
    public int timerSlack(long slackNs) {
        return c.prctl(PR_SET_TIMERSLACK, slackNs, 0, 0, 0) == 0 ? 0 : Native.getLastError();
    }
}
