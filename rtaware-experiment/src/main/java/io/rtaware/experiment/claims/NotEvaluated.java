package io.rtaware.experiment.claims;

/**
 * A claim these results cannot decide.
 *
 * @param id the claim's stable id, as {@link Claim#id()}
 * @param claim what the paper says
 * @param reason which data is missing
 */
public record NotEvaluated(String id, String claim, String reason) {
}
