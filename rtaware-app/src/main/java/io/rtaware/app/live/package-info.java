/**
 * The {@code --live}, {@code --live-bind}, {@code --live-port} and {@code --live-linger} options
 * of {@code run} and {@code bench}, turned into the {@code rtaware-live} module's
 * {@link io.rtaware.live.LiveOptions}.
 */
package io.rtaware.app.live;
