/**
 * The paper's claims and rtaware's own rules, each family one rule type that owns its stable id,
 * its words and how its verdict follows from an experiment's results; {@link
 * io.rtaware.experiment.claims.PaperClaims} lists them and judges an experiment.
 */
package io.rtaware.experiment.claims;
