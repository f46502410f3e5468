/**
 * The recorder's preallocated rings, one generic shape ({@link io.rtaware.record.ring.SlotRing}:
 * claim, fill, publish; one consumer drains in order) with its thread-safety contract in the
 * type's name: {@link io.rtaware.record.ring.SingleProducerRing} for rings that one thread fills
 * at a time (a key's producer, a task's thread, the ground-truth sampler), and
 * {@link io.rtaware.record.ring.MultiProducerRing} for the ring any thread may fill (monitor
 * events). The consumer is the recorder's writer thread; nothing locks or allocates.
 */
package io.rtaware.record.ring;
