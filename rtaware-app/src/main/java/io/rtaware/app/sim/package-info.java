/** Commands of the built-in simulator: serve it over Player, draw its world. */
package io.rtaware.app.sim;
