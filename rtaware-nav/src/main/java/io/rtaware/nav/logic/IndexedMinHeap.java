package io.rtaware.nav.logic;

import java.util.Arrays;

/**
 * A binary min-heap of int node indices keyed by double priorities, with decrease-key, over a
 * fixed range of nodes {@code 0..capacity-1}. All arrays are allocated at construction. Not
 * thread-safe.
 */
public final class IndexedMinHeap {

    private final int[] heap;
    private final int[] position;
    private final double[] priority;
    private int size;

    /** @param capacity number of distinct nodes (node indices are below it) */
    public IndexedMinHeap(int capacity) {
        this.heap = new int[capacity];
        this.position = new int[capacity];
        this.priority = new double[capacity];
        Arrays.fill(position, -1);
    }

    /** @return number of nodes in the heap */
    public int size() {
        return size;
    }

    /** @return true if empty */
    public boolean isEmpty() {
        return size == 0;
    }

    /**
     * @param node a node index
     * @return true if the node is in the heap
     */
    public boolean contains(int node) {
        return position[node] >= 0;
    }

    /**
     * Inserts a node, or lowers its priority if it is already in and the new one is lower.
     *
     * @param node node index
     * @param p priority
     */
    public void insertOrDecrease(int node, double p) {
        int pos = position[node];
        if (pos < 0) {
            pos = size++;
            heap[pos] = node;
            position[node] = pos;
            priority[node] = p;
            siftUp(pos);
        } else if (p < priority[node]) {
            priority[node] = p;
            siftUp(pos);
        }
    }

    /**
     * Removes the node with the lowest priority.
     *
     * @return its index
     * @throws IllegalStateException if empty
     */
    public int poll() {
        if (size == 0) {
            throw new IllegalStateException("heap is empty");
        }
        int top = heap[0];
        position[top] = -1;
        size--;
        if (size > 0) {
            int last = heap[size];
            heap[0] = last;
            position[last] = 0;
            siftDown(0);
        }
        return top;
    }

    /** Empties the heap in time proportional to its size. */
    public void clear() {
        for (int i = 0; i < size; i++) {
            position[heap[i]] = -1;
        }
        size = 0;
    }

    private void siftUp(int pos) {
        int node = heap[pos];
        double p = priority[node];
        while (pos > 0) {
            int parentPos = (pos - 1) >>> 1;
            int parent = heap[parentPos];
            if (priority[parent] <= p) {
                break;
            }
            heap[pos] = parent;
            position[parent] = pos;
            pos = parentPos;
        }
        heap[pos] = node;
        position[node] = pos;
    }

    private void siftDown(int pos) {
        int node = heap[pos];
        double p = priority[node];
        int half = size >>> 1;
        while (pos < half) {
            int child = 2 * pos + 1;
            int right = child + 1;
            if (right < size && priority[heap[right]] < priority[heap[child]]) {
                child = right;
            }
            if (priority[heap[child]] >= p) {
                break;
            }
            heap[pos] = heap[child];
            position[heap[child]] = pos;
            pos = child;
        }
        heap[pos] = node;
        position[node] = pos;
    }
}
