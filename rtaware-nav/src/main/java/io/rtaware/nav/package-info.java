/**
 * The paper's waypoint-navigation controller as a whole: its configuration
 * ({@link io.rtaware.nav.NavConfig}), the keys its behaviors share ({@link io.rtaware.nav.NavKeys}),
 * the composition that turns both into tasks for the monitor
 * ({@link io.rtaware.nav.NavController}), and its configuration as a recording's metadata, from
 * which replay rebuilds it ({@link io.rtaware.nav.ControllerMetadata}).
 */
package io.rtaware.nav;
