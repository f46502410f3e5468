package io.rtaware.experiment;

/**
 * One run the experiment will make.
 *
 * @param set the set's number, from 1
 * @param run the run's number within the set, from 1
 * @param periods the set
 */
public record PlannedRun(int set, int run, PeriodSet periods) {

    /** @return the run's folder name under {@code runs/}, e.g. {@code set2-run7} */
    public String folderName() {
        return "set" + set + "-run" + run;
    }
}
