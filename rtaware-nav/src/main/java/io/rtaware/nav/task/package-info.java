/**
 * The navigation behaviors as tasks on the rtaware core: each declares the keys it consumes and
 * produces, allocates its working memory in {@code initialize}, and runs its logic (from
 * {@link io.rtaware.nav.logic}) on the inputs the framework copied in, without allocating.
 * A task is run by one thread at a time; getters documented as thread-safe may be called from
 * any thread.
 */
package io.rtaware.nav.task;
