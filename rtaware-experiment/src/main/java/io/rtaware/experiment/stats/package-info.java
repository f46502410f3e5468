/**
 * Descriptive statistics of a sample; Welch's two-sided t-test between two samples (its degenerate
 * cases, too few values or no variance, reported as "n/a" with a reason, never NaN) and the
 * intervals of the difference of their means and the ratio of their variances; rates with Wilson
 * intervals; paired differences; the blocked comparison (two-way ANOVA without replication and
 * Friedman's test); Fisher's exact test.
 */
package io.rtaware.experiment.stats;
