package io.rtaware.experiment.claims;

/**
 * What a claim is judged on besides the paper's own course and top speed, in the claim's words
 * and in its id: {@code " on office"} and {@code "-on-office"}, {@code " (at 0.5 m/s)"} and
 * {@code "@0.5mps"}. The id is made here, with the words, and never read back from them: a course
 * named by a path ({@code /data/courses/hall.yaml}) has its file's base name in the id.
 *
 * @param words appended to the claim's words
 * @param idSuffix appended to the family's id
 */
record Scope(String words, String idSuffix) {

    /** The paper's course at the paper's top speed. */
    static final Scope PAPER = new Scope("", "");

    /** The paper's course, as experiments name it. */
    static final String PAPER_COURSE = "paper-room";

    /**
     * @param scenario a course, or null
     * @return this scope on that course: unchanged on the paper's room (or when none is named)
     */
    Scope on(String scenario) {
        if (scenario == null || PAPER_COURSE.equals(scenario)) {
            return this;
        }
        String base = scenario.substring(Math.max(scenario.lastIndexOf('/'), scenario.lastIndexOf('\\')) + 1)
                .replaceFirst("\\.(ya?ml)$", "").replaceAll("[^A-Za-z0-9._-]", "-");
        return new Scope(words + " on " + scenario, idSuffix + "-on-" + (base.isEmpty() ? "course" : base));
    }

    /**
     * @param speed a top speed in words, {@code "0.5 m/s"} or {@code "run's default top speed"}
     * @return this scope at that top speed
     */
    Scope at(String speed) {
        return new Scope(words + " (at " + speed + ")", idSuffix + "@" + speed.replace(" m/s", "mps")
                .replace("run's default top speed", "default").replace(' ', '-'));
    }
}
