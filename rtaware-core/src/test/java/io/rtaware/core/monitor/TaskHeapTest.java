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
}
