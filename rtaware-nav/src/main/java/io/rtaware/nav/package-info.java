/**
 * The paper's waypoint-navigation controller as a whole: its configuration
 * ({@link io.rtaware.nav.NavConfig}), the keys its behaviors share ({@link io.rtaware.nav.NavKeys})
 * and the composition that turns both into tasks for the monitor
 * ({@link io.rtaware.nav.NavController}).
 */
package io.rtaware.nav;
