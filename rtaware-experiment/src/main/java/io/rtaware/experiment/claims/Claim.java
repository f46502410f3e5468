package io.rtaware.experiment.claims;

/**
 * One claim with its verdict.
 *
 * @param id the claim's stable id, e.g. {@code table1-set1-faster} or {@code slow-hits@0.5mps}: its
 *     family's id ({@link ClaimRule#id()}) and the scope it was judged on, never derived from its words;
 *     docs quote its verdict by it ({@code claim `FOLDER/ID`: VERDICT})
 * @param claim what the paper says (with the course and top speed it was judged on, when they are
 *     not the paper's)
 * @param verdict what the results say
 * @param evidence the numbers the verdict rests on
 * @param rule how the verdict follows from the numbers
 */
public record Claim(String id, String claim, Verdict verdict, String evidence, String rule) {
}
