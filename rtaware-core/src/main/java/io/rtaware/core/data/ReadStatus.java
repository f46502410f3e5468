package io.rtaware.core.data;

/**
 * What a task's copy of an input holds at the start of its cycle (after Orocos' FlowStatus).
 */
public enum ReadStatus {
    /** Never written by its producer: the buffer holds the factory's empty value. */
    NONE,
    /** Unchanged since this task's previous cycle. */
    OLD,
    /** Committed by the producer since this task's previous cycle. */
    NEW
}
