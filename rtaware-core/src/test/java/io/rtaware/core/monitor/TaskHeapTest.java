package io.rtaware.core.monitor;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** The pool's timer structure against a sorted list: order by key, ties by slot. */
class TaskHeapTest {

    @Test
    void popsInKeyOrderWithTiesByLowerSlot() {
        TaskHeap heap = new TaskHeap(6);
        heap.push(3, 20);
        heap.push(5, 10);
        heap.push(0, 20);
        heap.push(4, 10);
        heap.push(1, 30);
        heap.push(2, 20);
        assertEquals(10, heap.peekKey());
        int[] order = new int[6];
        for (int i = 0; i < order.length; i++) {
            order[i] = heap.pop();
        }
        assertEquals(List.of(4, 5, 0, 2, 3, 1), List.of(order[0], order[1], order[2], order[3], order[4], order[5]));
        assertEquals(0, heap.size());
        assertEquals(Long.MAX_VALUE, heap.peekKey());
    }

    /** Random pushes and pops with many equal keys (tasks released at the same instant), checked against a sort. */
    @Test
    void agreesWithASortedListUnderRandomPushesAndPops() {
        SplittableRandom random = new SplittableRandom(16);
        for (int round = 0; round < 200; round++) {
            int capacity = 1 + random.nextInt(300);
            TaskHeap heap = new TaskHeap(capacity);
            List<long[]> reference = new ArrayList<>();
            boolean[] inHeap = new boolean[capacity];
            for (int op = 0; op < 2000; op++) {
                boolean push = reference.isEmpty() || (reference.size() < capacity && random.nextBoolean());
                if (push) {
                    int slot = random.nextInt(capacity);
                    while (inHeap[slot]) {
                        slot = (slot + 1) % capacity;
                    }
                    long key = random.nextInt(8);
                    heap.push(slot, key);
                    inHeap[slot] = true;
                    reference.add(new long[] {key, slot});
                } else {
                    reference.sort(Comparator.<long[]>comparingLong(e -> e[0]).thenComparingLong(e -> e[1]));
                    long[] expected = reference.remove(0);
                    assertEquals(expected[0], heap.peekKey());
                    assertEquals(expected[1], heap.peek());
                    int slot = heap.pop();
                    assertEquals(expected[1], slot, "round " + round + ", operation " + op);
                    inHeap[slot] = false;
                }
                assertEquals(reference.size(), heap.size());
            }
        }
    }

    /**
     * What a pool does with it: tasks of a few periods and phases popped when due and pushed back
     * keyed by their next release (sometimes a period or two later, as after a skip), checked
     * against a sort; with tasks in phase the pushes go to the sorted run, with others to the heap.
     */
    @Test
    void agreesWithASortedListUnderPeriodicPutBacks() {
        SplittableRandom random = new SplittableRandom(36);
        for (int round = 0; round < 100; round++) {
            int capacity = 1 + random.nextInt(200);
            long[] period = new long[capacity];
            TaskHeap heap = new TaskHeap(capacity);
            List<long[]> reference = new ArrayList<>();
            for (int slot = 0; slot < capacity; slot++) {
                period[slot] = 10 * (1 + random.nextInt(round % 2 == 0 ? 1 : 4));
                long first = round % 4 == 3 ? random.nextInt(10) : 0;
                heap.push(slot, first);
                reference.add(new long[] {first, slot});
            }
            for (int op = 0; op < 3000; op++) {
                reference.sort(Comparator.<long[]>comparingLong(e -> e[0]).thenComparingLong(e -> e[1]));
                long[] expected = reference.remove(0);
                assertEquals(expected[0], heap.peekKey(), "round " + round + ", operation " + op);
                int slot = heap.pop();
                assertEquals(expected[1], slot, "round " + round + ", operation " + op);
                long next = expected[0] + period[slot] * (random.nextInt(20) == 0 ? 2 : 1);
                heap.push(slot, next);
                reference.add(new long[] {next, slot});
                assertEquals(reference.size(), heap.size());
            }
        }
    }

    @Test
    void tasksInPhaseStayInTheSortedRunAndNeverMeetTheHeap() {
        TaskHeap heap = new TaskHeap(1000);
        for (int slot = 0; slot < 1000; slot++) {
            heap.push(slot, 0);
        }
        for (long release = 0; release < 5; release++) {
            for (int expected = 0; expected < 1000; expected++) {
                assertEquals(1000, heap.sortedRunSize(), "every node in the run");
                assertEquals(release * 10, heap.peekKey());
                int slot = heap.pop();
                assertEquals(expected, slot, "slot order within one release instant");
                heap.push(slot, (release + 1) * 10);
            }
        }
        heap.push(heap.pop(), 5);
        assertEquals(999, heap.sortedRunSize(), "a node out of order goes to the heap");
        assertEquals(5, heap.peekKey(), "and comes first all the same");
        heap.clear();
        assertEquals(0, heap.size());
    }
}
