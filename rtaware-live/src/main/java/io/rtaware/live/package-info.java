/**
 * {@code --live}: a browser view of a running monitor. A publisher thread (never a task thread)
 * samples the monitor's live counters, feed statistics and key values at a bounded rate, builds
 * one JSON snapshot at a time and hands it to a loopback HTTP server (the JDK's built-in one)
 * that serves a static page, the latest snapshot and a Server-Sent Events stream with a
 * latest-value slot per browser.
 */
package io.rtaware.live;
