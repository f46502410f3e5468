/**
 * JMH micro-benchmarks of rtaware's hot paths: the data store's copy-in and commit, the
 * monitor's per-release bookkeeping, the Player decoder, the simulator's ray casting and world
 * step, and the navigation grid update and Dijkstra plan. Build with
 * {@code ./mvnw -B -q -pl rtaware-bench -am package -DskipTests} and run
 * {@code java -jar rtaware-bench/target/benchmarks.jar [regex]}. The subpackages hold the
 * benchmark engine of {@code rtaware bench}: synthetic load ({@code load}) and the executor
 * comparison ({@code compare}).
 */
package io.rtaware.bench;
