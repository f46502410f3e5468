/**
 * Where the libraries' log records go: one configuration, set once by the program that uses
 * them (the {@code rtaware} command sets it), instead of java.util.logging's two-line console
 * records.
 */
package io.rtaware.core.log;
