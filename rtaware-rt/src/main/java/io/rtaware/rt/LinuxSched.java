package io.rtaware.rt;

/**
 * The few Linux calls real-time threads need, each acting on the calling thread and returning
 * 0 or an errno. An interface so the fallback can be tested without privileges.
 * Implementations are thread-safe.
 */
public interface LinuxSched {

    /** {@code SCHED_OTHER}, the normal time-sharing policy. */
    int SCHED_OTHER = 0;
    /** {@code SCHED_FIFO}, fixed-priority real-time. */
    int SCHED_FIFO = 1;

    /**
     * @param priority 1..99
     * @return 0, or the errno of {@code sched_setscheduler(0, SCHED_FIFO, priority)}
     */
    int setFifo(int priority);

    /** @return the calling thread's policy ({@link #SCHED_FIFO}, ...), or -1 on error */
    int scheduler();

    /** @return the calling thread's static priority (1..99 under SCHED_FIFO, 0 otherwise), or -1 on error */
    int priority();

    /**
     * @param cpu a CPU number
     * @return 0, or the errno of {@code sched_setaffinity} to that CPU alone
     */
    int pinTo(int cpu);

    /**
     * @param slackNs timer slack in nanoseconds
     * @return 0, or the errno of {@code prctl(PR_SET_TIMERSLACK, slackNs)}
     */
    int timerSlack(long slackNs);
}
