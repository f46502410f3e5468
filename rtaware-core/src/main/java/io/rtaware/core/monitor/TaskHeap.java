package io.rtaware.core.monitor;

/**
 * A min-heap of task slots (0..capacity-1) ordered by a key per slot, ties by the lower slot
 * (registration order): the pooled executor's timer structure. Arrays only, sized once: pushing
 * and popping never allocate. Not thread-safe (the pool's lock guards it).
 *
 * <p>Laid out for a worker whose caches the tasks' own objects keep evicting (10 000 tasks
 * released at one instant): four children per node instead of two, so a pop walks half as many
 * levels, and each node's key and slot stored at its heap position, so the four children a level
 * compares lie side by side (four keys in 32 bytes, four slots in 16) instead of being looked up
 * through the slots in a key array indexed by slot, one cache line each. The pool's profile at
 * 10 000 in-phase tasks put a quarter of the workers' samples in the binary heap's pop before.
 *
 * <p>Beside the heap, a <em>sorted run</em>: a ring of nodes in order, to which a push that comes
 * after every node already in the run is appended, and from whose head a pop takes when that
 * comes before the heap's top. Periodic tasks put back in the order they ran (each keyed by its
 * next release) are such pushes: in steady state, releases of tasks in phase go in and out of
 * the run, in order, at O(1) and in sequential memory, and the heap holds only what came out of
 * order (a task with another period or phase). Still sized once, still never allocating.
 */
final class TaskHeap {

    /** Children per node: node {@code i}'s are {@code 4i + 1 .. 4i + 4}. */
    private static final int ARITY_SHIFT = 2;

    /** The key of the node at each heap position. */
    private final long[] keys;
    /** The slot of the node at each heap position. */
    private final int[] slots;
    /** Nodes in the heap proper. */
    private int size;
    /** The sorted run: keys and slots in order from {@code runHead}, {@code runSize} of them, as a ring. */
    private final long[] runKeys;
    private final int[] runSlots;
    private int runHead;
    private int runSize;

    /** @param capacity the number of slots */
    TaskHeap(int capacity) {
        keys = new long[capacity];
        slots = new int[capacity];
        runKeys = new long[capacity];
        runSlots = new int[capacity];
    }

    /** @return the nodes in the structure (heap and sorted run) */
    int size() {
        return size + runSize;
    }

    /** @return the nodes in the sorted run (tests: in-phase tasks in steady state never meet the heap) */
    int sortedRunSize() {
        return runSize;
    }

    /** @return the smallest key, or {@link Long#MAX_VALUE} if empty */
    long peekKey() {
        return runFirst() ? runKeys[runHead] : size == 0 ? Long.MAX_VALUE : keys[0];
    }

    /** Empties the structure. */
    void clear() {
        size = 0;
        runSize = 0;
        runHead = 0;
    }

    /** @return the slot with the smallest key; only when not empty */
    int peek() {
        return runFirst() ? runSlots[runHead] : slots[0];
    }

    /** @return whether the next node is the sorted run's head (else the heap's top, or none) */
    private boolean runFirst() {
        return runSize > 0 && (size == 0 || before(runKeys[runHead], runSlots[runHead], keys[0], slots[0]));
    }

    /**
     * @param slot a slot not in the structure
     * @param key its key
     */
    void push(int slot, long key) {
        if (runSize > 0) {
            int tail = ring(runHead + runSize - 1);
            if (before(key, slot, runKeys[tail], runSlots[tail])) {
                pushOnHeap(slot, key);
                return;
            }
        }
        int next = ring(runHead + runSize);
        runKeys[next] = key;
        runSlots[next] = slot;
        runSize++;
    }

    /** @return position {@code i} of the sorted run's ring, for {@code i} below twice its length */
    private int ring(int i) {
        return i >= runKeys.length ? i - runKeys.length : i;
    }

    private void pushOnHeap(int slot, long key) {
        int i = size++;
        while (i > 0) {
            int parent = (i - 1) >>> ARITY_SHIFT;
            long parentKey = keys[parent];
            int parentSlot = slots[parent];
            if (before(parentKey, parentSlot, key, slot)) {
                break;
            }
            keys[i] = parentKey;
            slots[i] = parentSlot;
            i = parent;
        }
        keys[i] = key;
        slots[i] = slot;
    }

    /** @return the slot with the smallest key, removed; only when not empty */
    int pop() {
        if (runFirst()) {
            int top = runSlots[runHead];
            runHead = ring(runHead + 1);
            runSize--;
            return top;
        }
        return popHeap();
    }

    private int popHeap() {
        int top = slots[0];
        int n = --size;
        long key = keys[n];
        int slot = slots[n];
        int i = 0;
        while (true) {
            int first = (i << ARITY_SHIFT) + 1;
            if (first >= n) {
                break;
            }
            int least = first;
            long leastKey = keys[first];
            int leastSlot = slots[first];
            int end = Math.min(first + (1 << ARITY_SHIFT), n);
            for (int child = first + 1; child < end; child++) {
                long childKey = keys[child];
                int childSlot = slots[child];
                if (before(childKey, childSlot, leastKey, leastSlot)) {
                    least = child;
                    leastKey = childKey;
                    leastSlot = childSlot;
                }
            }
            if (before(key, slot, leastKey, leastSlot)) {
                break;
            }
            keys[i] = leastKey;
            slots[i] = leastSlot;
            i = least;
        }
        keys[i] = key;
        slots[i] = slot;
        return top;
    }

    /** @return whether node (keyA, slotA) comes before node (keyB, slotB): by key, ties by slot */
    private static boolean before(long keyA, int slotA, long keyB, int slotB) {
        return keyA < keyB || (keyA == keyB && slotA < slotB);
    }
}
