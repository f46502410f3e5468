/** {@code rtaware analyze}: advice and schedulability of a saved report. */
package io.rtaware.app.analyze;
