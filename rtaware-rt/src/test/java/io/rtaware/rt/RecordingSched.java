package io.rtaware.rt;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

/** A kernel that records every call ({@code fifo 80}, {@code pin 1}, {@code slack 1}) and answers as told. */
final class RecordingSched implements LinuxSched {
    final List<String> calls = new CopyOnWriteArrayList<>();
    private final int fifoAnswer;
    private final int slackAnswer;

    /**
     * @param fifoAnswer what {@code sched_setscheduler} returns: 0, or an errno (1 is EPERM)
     * @param slackAnswer what {@code prctl(PR_SET_TIMERSLACK)} returns: 0, or an errno
     */
    RecordingSched(int fifoAnswer, int slackAnswer) {
        this.fifoAnswer = fifoAnswer;
        this.slackAnswer = slackAnswer;
    }

    @Override
    public int setFifo(int priority) {
        calls.add("fifo " + priority);
        return fifoAnswer;
    }

    @Override
    public int scheduler() {
        return SCHED_OTHER;
    }

    @Override
    public int priority() {
        return 0;
    }

    @Override
    public int pinTo(int cpu) {
        calls.add("pin " + cpu);
        return 0;
    }

    @Override
    public int timerSlack(long slackNs) {
        calls.add("slack " + slackNs);
        return slackAnswer;
    }
}
