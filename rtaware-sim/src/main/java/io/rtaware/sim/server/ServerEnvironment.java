package io.rtaware.sim.server;

import io.rtaware.core.time.Clock;
import io.rtaware.core.time.SystemClock;
import java.io.IOException;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.concurrent.ThreadFactory;
import java.util.concurrent.locks.LockSupport;

/**
 * What the server takes from the operating system: accepting a connection, client threads,
 * waiting, wall time. {@link #system()} in production; tests replace parts to inject failures
 * (an accept that fails as when file descriptors run out, a thread factory that cannot create
 * threads) and to back off without sleeping.
 *
 * @param accept accepts one connection
 * @param clientThreads makes the reader and writer threads of each client
 * @param pause waits between failed accepts
 * @param wallClock wall time, for message timeouts
 */
record ServerEnvironment(Accept accept, ThreadFactory clientThreads, Pause pause, Clock wallClock) {

    /** Accepts one connection on the server socket. */
    interface Accept {
        Socket accept(ServerSocket server) throws IOException;
    }

    /** Waits. */
    interface Pause {
        void pause(long nanos) throws InterruptedException;
    }

    /**
     * @return the real thing: {@link ServerSocket#accept()}, plain threads, a park (which closing
     *     the accept loop's {@link io.rtaware.core.agent.AgentThread} cuts short), the system clock
     */
    static ServerEnvironment system() {
        return new ServerEnvironment(ServerSocket::accept, Thread::new, LockSupport::parkNanos, new SystemClock());
    }
}
