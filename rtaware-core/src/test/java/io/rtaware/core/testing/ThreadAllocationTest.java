package io.rtaware.core.testing;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.core.agent.ThreadNames;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

/** The allocation snapshot names the threads that allocated, ordered by latches (no timing). */
class ThreadAllocationTest {

    private static volatile byte[] sink;

    /** A thread that allocates 10 000 bytes once let go, then waits until it may end. */
    private static final class Allocator {
        final CountDownLatch go = new CountDownLatch(1);
        final CountDownLatch allocated = new CountDownLatch(1);
        final Thread thread;

        Allocator(String name, CountDownLatch mayEnd) {
            thread = new Thread(() -> {
                try {
                    go.await();
                    sink = new byte[10_000];
                    allocated.countDown();
                    mayEnd.await();
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }, name);
            thread.start();
        }

        /** Lets it allocate and waits until it has. */
        void allocate() throws InterruptedException {
            go.countDown();
            assertTrue(allocated.await(10, TimeUnit.SECONDS));
        }
    }

    @Test
    void namesTheFrameworkThreadThatAllocatedAndHowMuch() throws Exception {
        CountDownLatch mayEnd = new CountDownLatch(1);
        Allocator task = new Allocator("rtaware-alloc-test", mayEnd);
        Thread idle = new Thread(() -> {
            try {
                mayEnd.await();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }, "rtaware-idle-test");
        idle.start();
        try {
            while (idle.getState() != Thread.State.WAITING || task.thread.getState() != Thread.State.WAITING) {
                Thread.onSpinWait(); // both parked in await (which allocates its queue node) before the snapshot
            }
            ThreadAllocation.prepare();
            ThreadAllocation snapshot = ThreadAllocation.ofFrameworkThreads();
            task.allocate();
            String threads = snapshot.allocatingThreads();
            Matcher m = Pattern.compile("rtaware-alloc-test (\\d+) B").matcher(threads);
            assertTrue(m.find(), threads);
            assertTrue(Long.parseLong(m.group(1)) >= 10_000, threads);
            assertTrue(snapshot.allocatedSince() >= 10_000);
            assertEquals(-1, threads.indexOf("rtaware-idle-test"), "a thread that allocated nothing is not named: " + threads);
        } finally {
            mayEnd.countDown();
            task.thread.join();
            idle.join();
        }
    }

    @Test
    void aThreadGoneByEitherReadCountsNothing() {
        assertArrayEquals(new long[] {30, 0, 0, 0}, ThreadAllocation.between(new long[] {10, 5, 7, -1},
                new long[] {40, -1, 7, 9}));
    }

    @Test
    void threadsKnownByIdAreNamedByIt() throws Exception {
        CountDownLatch mayEnd = new CountDownLatch(1);
        Allocator worker = new Allocator("any-name", mayEnd);
        try {
            ThreadAllocation snapshot = ThreadAllocation.ofThreadIds(worker.thread.getId());
            worker.allocate();
            assertEquals(1, snapshot.threads());
            assertTrue(snapshot.allocatedSince() >= 10_000, snapshot.allocatingThreads());
            assertTrue(snapshot.allocatingThreads().startsWith("thread " + worker.thread.getId() + " "),
                    snapshot.allocatingThreads());
        } finally {
            mayEnd.countDown();
            worker.thread.join();
        }
    }

    /** The live view's publisher (named {@link ThreadNames#LIVE_PUBLISHER} in rtaware-live) builds JSON off the tasks' path. */
    @Test
    void theLiveViewsPublisherIsAnObserverNotAFrameworkThread() throws Exception {
        CountDownLatch snapshotTaken = new CountDownLatch(1);
        CountDownLatch allocated = new CountDownLatch(1);
        CountDownLatch mayEnd = new CountDownLatch(1);
        Thread publisher = new Thread(() -> {
            try {
                snapshotTaken.await();
                sink = new byte[10_000]; // a snapshot's JSON, off the tasks' path
                allocated.countDown();
                mayEnd.await(); // alive while asked: a thread that ended has no count
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }, ThreadNames.LIVE_PUBLISHER);
        publisher.start();
        try {
            while (publisher.getState() != Thread.State.WAITING) {
                Thread.onSpinWait();
            }
            ThreadAllocation.prepare();
            ThreadAllocation snapshot = ThreadAllocation.ofFrameworkThreads();
            snapshotTaken.countDown();
            assertTrue(allocated.await(10, TimeUnit.SECONDS));
            assertEquals(-1, snapshot.allocatingThreads().indexOf(ThreadNames.LIVE_PUBLISHER),
                    "bench --live --fail-on-alloc counted the publisher's JSON as the framework's: "
                            + snapshot.allocatingThreads());
        } finally {
            snapshotTaken.countDown();
            mayEnd.countDown();
            publisher.join();
        }
    }
}
