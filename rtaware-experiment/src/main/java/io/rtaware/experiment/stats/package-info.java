/**
 * Descriptive statistics of a sample and Welch's two-sided t-test between two samples, with
 * degenerate cases (too few values, no variance) reported as "n/a" with a reason, never NaN.
 */
package io.rtaware.experiment.stats;
