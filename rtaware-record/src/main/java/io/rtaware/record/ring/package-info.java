/**
 * The positions of the recorder's preallocated rings, with their thread-safety contract in their
 * type's name: {@link io.rtaware.record.ring.SingleProducerSequence} for rings that one thread
 * fills at a time (a key's producer, a task's thread, the ground-truth sampler), and
 * {@link io.rtaware.record.ring.MultiProducerSequence} for the ring any thread may fill (monitor
 * events). Both have one consumer, the recorder's writer thread, and neither locks nor allocates.
 */
package io.rtaware.record.ring;
