package io.rtaware.record;

import java.io.IOException;

/** A ring of the recorder, as its writer thread sees it. */
interface RecorderRing {

    /**
     * Encodes and writes every record published so far, and frees their slots.
     *
     * @param sink where the messages go
     * @param scratch encoding buffers
     * @return records written
     * @throws IOException if writing fails
     */
    int drain(MessageSink sink, WriterScratch scratch) throws IOException;

    /** Frees every published record unwritten (after a write failure, so producers only drop). */
    void discard();
}
