package io.rtaware.app.experiment;

import io.rtaware.experiment.report.MapBackground;

/**
 * The picture of a course drawn behind the experiment's paths. This is the one place where the
 * scenario loader (walls, obstacles, waypoints) is connected to the report; until a scenario
 * can be loaded here, the figure shows the paths alone.
 */
final class CourseBackgrounds {

    private CourseBackgrounds() {
    }

    /**
     * @param scenario {@code paper-room} or a scenario file, as given to {@code run}
     * @return the course's background, or {@link MapBackground#none()}
     */
    static MapBackground forScenario(String scenario) {
        return MapBackground.none();
    }
}
