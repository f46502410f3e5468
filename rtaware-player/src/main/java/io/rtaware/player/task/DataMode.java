package io.rtaware.player.task;

/** How the server delivers data. Immutable; thread-safe. */
public enum DataMode {
    /** The server pushes data as it is published; a replace rule keeps only the newest. */
    PUSH,
    /** The task asks for each round of data and reads until the server's SYNCH. */
    PULL
}
