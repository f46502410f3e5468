/** Test doubles of the core's data store and task setup, and a tiny simulated room. */
package io.rtaware.nav.testing;
