package io.rtaware.core;

import io.rtaware.core.task.Task;
import io.rtaware.core.task.TaskSetup;

/** A test task made of two lambdas. */
public final class FnTask implements Task {

    /** Initialization body. */
    @FunctionalInterface
    public interface Init {
        void initialize(TaskSetup setup) throws Exception;
    }

    /** Execution body. */
    @FunctionalInterface
    public interface Body {
        void execute(long nowNs) throws Exception;
    }

    private final Init init;
    private final Body body;
    public int terminations;

    public FnTask(Init init, Body body) {
        this.init = init;
        this.body = body;
    }

    /** A task with no data that runs {@code body}. */
    public static FnTask of(Body body) {
        return new FnTask(s -> { }, body);
    }

    @Override
    public void initialize(TaskSetup setup) throws Exception {
        init.initialize(setup);
    }

    @Override
    public void execute(long nowNs) throws Exception {
        body.execute(nowNs);
    }

    @Override
    public void terminate() {
        terminations++;
    }
}
