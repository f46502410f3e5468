/**
 * Recording a run to MCAP: {@link io.rtaware.record.RunRecorder} takes every commit, every cycle
 * and every monitor event from the task threads into preallocated rings (no allocation, no
 * blocking; a full ring drops and counts), and a writer thread of its own encodes and writes
 * them.
 */
package io.rtaware.record;
