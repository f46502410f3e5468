/**
 * The shared data store: latest-value state variables, never queues (the paper's design,
 * after Chimera's port-based objects). Each key has exactly one producer and any number of
 * consumers; each holds the newest value, a generation counter and the commit time. Consumers
 * copy into buffers they own at the start of every cycle under a shared read lock; producers
 * commit at the end of the cycle under the write lock. All buffers are allocated during
 * initialization, so steady-state cycles allocate nothing.
 */
package io.rtaware.core.data;
