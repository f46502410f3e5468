package io.rtaware.app.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.live.LiveView;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

/** The allocation snapshot names the threads that allocated, ordered by latches (no timing). */
class ThreadAllocationTest {

    private static volatile byte[] sink;

    @Test
    void namesTheFrameworkThreadThatAllocatedAndHowMuch() throws Exception {
        CountDownLatch snapshotTaken = new CountDownLatch(1);
        CountDownLatch allocated = new CountDownLatch(1);
        CountDownLatch mayEnd = new CountDownLatch(1);
        Thread task = new Thread(() -> {
            try {
                snapshotTaken.await();
                sink = new byte[10_000];
                allocated.countDown();
                mayEnd.await();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }, "rtaware-alloc-test");
        Thread idle = new Thread(() -> {
            try {
                mayEnd.await();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }, "rtaware-idle-test");
        task.start();
        idle.start();
        try {
            while (idle.getState() != Thread.State.WAITING || task.getState() != Thread.State.WAITING) {
                Thread.onSpinWait(); // both parked in await (which allocates its queue node) before the snapshot
            }
            ThreadAllocation.prepare();
            ThreadAllocation snapshot = ThreadAllocation.ofFrameworkThreads();
            snapshotTaken.countDown();
            assertTrue(allocated.await(10, TimeUnit.SECONDS));
            String threads = snapshot.allocatingThreads();
            Matcher m = Pattern.compile("rtaware-alloc-test (\\d+) B").matcher(threads);
            assertTrue(m.find(), threads);
            assertTrue(Long.parseLong(m.group(1)) >= 10_000, threads);
            assertTrue(snapshot.allocatedSince() >= 10_000);
            assertEquals(-1, threads.indexOf("rtaware-idle-test"), "a thread that allocated nothing is not named: " + threads);
        } finally {
            mayEnd.countDown();
            task.join();
            idle.join();
        }
    }

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
        }, LiveView.PUBLISHER_THREAD);
        publisher.start();
        try {
            while (publisher.getState() != Thread.State.WAITING) {
                Thread.onSpinWait();
            }
            ThreadAllocation.prepare();
            ThreadAllocation snapshot = ThreadAllocation.ofFrameworkThreads();
            snapshotTaken.countDown();
            assertTrue(allocated.await(10, TimeUnit.SECONDS));
            assertEquals(-1, snapshot.allocatingThreads().indexOf(LiveView.PUBLISHER_THREAD),
                    "bench --live --fail-on-alloc counted the publisher's JSON as the framework's: "
                            + snapshot.allocatingThreads());
        } finally {
            snapshotTaken.countDown();
            mayEnd.countDown();
            publisher.join();
        }
    }
}
