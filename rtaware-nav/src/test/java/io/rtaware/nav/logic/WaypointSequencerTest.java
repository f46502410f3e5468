package io.rtaware.nav.logic;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.robot.msg.GoalSet;
import org.junit.jupiter.api.Test;

class WaypointSequencerTest {

    @Test
    void progressesThroughTheWaypointsAndFinishes() {
        WaypointSequencer seq = new WaypointSequencer(8, 0.25);
        GoalSet course = new GoalSet(4);
        course.add(1, 1, 0);
        course.add(2, 1, 1);
        seq.setWaypoints(course);
        assertEquals(2, seq.count());
        assertFalse(seq.isDone());
        long firstId = seq.currentGoalId();
        assertFalse(seq.update(0, 0), "1 m away");
        assertTrue(seq.update(0.8, 0.1), "within 0.25 m");
        assertEquals(1, seq.reached());
        assertEquals(1.0, seq.currentYM());
        assertNotEquals(firstId, seq.currentGoalId());
        assertFalse(seq.update(0.8, 0.1));
        assertEquals(Math.hypot(0.2, 0.9), seq.distanceToFinishM(0.8, 0.1), 1e-12);
        assertTrue(seq.update(1.1, 1.1));
        assertTrue(seq.isDone());
        assertEquals(2, seq.reached());
        assertFalse(seq.update(1, 1), "nothing more to reach");
        assertEquals(1.0, seq.currentXM(), "the finish stays the current point when done");
    }

    @Test
    void replacingTheCourseRestartsItWithNewGoalIds() {
        WaypointSequencer seq = new WaypointSequencer(8, 0.25);
        GoalSet course = new GoalSet(4);
        course.add(1, 1, 0);
        seq.setWaypoints(course);
        long id = seq.currentGoalId();
        seq.update(1, 0);
        assertTrue(seq.isDone());
        seq.setWaypoints(course);
        assertFalse(seq.isDone());
        assertEquals(0, seq.index());
        assertNotEquals(id, seq.currentGoalId());
    }
}
