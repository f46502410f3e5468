/**
 * Timelines of a run: {@link io.rtaware.core.trace.TraceRecorder} records the monitor's events
 * into a bounded, preallocated ring buffer and writes them as a Chrome trace event file that
 * the Perfetto UI (https://ui.perfetto.dev) and chrome://tracing open.
 */
package io.rtaware.core.trace;
