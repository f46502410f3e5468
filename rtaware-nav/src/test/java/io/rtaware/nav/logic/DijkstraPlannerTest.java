package io.rtaware.nav.logic;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.robot.msg.GoalSet;
import io.rtaware.robot.msg.OccupancyGrid;
import io.rtaware.robot.msg.PlannedPath;
import org.junit.jupiter.api.Test;

/** Dijkstra on small grids with 1 m cells, against hand-computed shortest path costs. */
class DijkstraPlannerTest {

    private static final double SQRT2 = Math.sqrt(2);
    private final GoalRegistry goals = new GoalRegistry(2, 16);
    private final PlannedPath path = new PlannedPath(64);

    /** Rows top (highest y) first: '.' free, '#' occupied, '?' unknown. */
    private static OccupancyGrid grid(String... rows) {
        int h = rows.length;
        int w = rows[0].length();
        OccupancyGrid g = new OccupancyGrid(w * h);
        g.setGeometry(w, h, 1.0, 0, 0);
        for (int r = 0; r < h; r++) {
            int y = h - 1 - r;
            for (int x = 0; x < w; x++) {
                char c = rows[r].charAt(x);
                g.cells[y * w + x] = c == '#' ? OccupancyGrid.OCCUPIED : c == '?' ? OccupancyGrid.UNKNOWN
                        : OccupancyGrid.FREE;
            }
        }
        return g;
    }

    private DijkstraPlanner planner(OccupancyGrid g, double inflationM, double unknownFactor) {
        DijkstraPlanner p = new DijkstraPlanner(g.width() * g.height(), inflationM, unknownFactor);
        p.setMap(g);
        return p;
    }

    @Test
    void straightAndDiagonalCostsOnAnOpenGrid() {
        DijkstraPlanner p = planner(grid(".....", ".....", ".....", ".....", "....."), 0, 2);
        goals.add(0, 1, 4.5, 0.5);
        assertTrue(p.plan(0.5, 0.5, goals, path));
        assertEquals(4.0, path.costM, 1e-9);
        assertEquals(5, path.count());
        goals.remove(0, 1);
        goals.add(0, 2, 4.5, 4.5);
        assertTrue(p.plan(0.5, 0.5, goals, path));
        assertEquals(4 * SQRT2, path.costM, 1e-9);
        goals.remove(0, 2);
        goals.add(0, 3, 4.5, 2.5);
        assertTrue(p.plan(0.5, 0.5, goals, path));
        assertEquals(2 * SQRT2 + 2, path.costM, 1e-9, "knight-like move: two diagonals and two straights");
        assertEquals(0.5, path.xM[0]);
        assertEquals(4.5, path.xM[path.count() - 1]);
        assertEquals(2.5, path.yM[path.count() - 1]);
        assertEquals(3, path.goalId);
        assertEquals(0, path.requesterIndex);
    }

    @Test
    void wallForcesADetourWithoutCuttingCorners() {
        DijkstraPlanner p = planner(grid(
                ".....",
                ".###.",
                ".....",
                "....."), 0, 2);
        // From (2,3) (above the wall) to (2,1) (below it): around an end of the wall.
        goals.add(0, 1, 2.5, 1.5);
        assertTrue(p.plan(2.5, 3.5, goals, path));
        // The diagonal (1,3)->(0,2) would cut the corner of the wall cell (1,2), so the path is
        // (2,3) (1,3) (0,3) (0,2) (0,1) (1,1) (2,1): six straight moves.
        assertEquals(6.0, path.costM, 1e-9);
    }

    @Test
    void inflationKeepsPathsAwayFromObstacles() {
        String[] rows = {
            ".......",
            ".......",
            "...#...",
            ".......",
            "......."};
        DijkstraPlanner bare = planner(grid(rows), 0, 2);
        goals.add(0, 1, 6.5, 2.5);
        assertTrue(bare.plan(0.5, 2.5, goals, path));
        assertEquals(4 + 2 * SQRT2, path.costM, 1e-9, "around the single cell, no inflation");
        // Inflating by 1 m blocks the 4-neighbours of the obstacle too: a plus shape (2,2),(4,2),(3,1),(3,3).
        DijkstraPlanner inflated = planner(grid(rows), 1.0, 2);
        assertTrue(inflated.plan(0.5, 2.5, goals, path));
        // Around through the outer row: (0,2) (1,1) (2,0) (3,0) (4,0) (5,1) (6,2), four diagonals and two
        // straights; the row next to the plus is closed by the no-corner-cutting rule.
        assertEquals(2 + 4 * SQRT2, path.costM, 1e-9);
    }

    @Test
    void robotStandingInAnInflatedCellDrivesOut() {
        DijkstraPlanner p = planner(grid(
                ".....",
                ".....",
                "#....",
                ".....",
                "....."), 1.0, 2);
        goals.add(0, 1, 4.5, 2.5);
        assertTrue(p.plan(1.5, 2.5, goals, path), "start (1,2) is inflated by the obstacle at (0,2)");
        assertEquals(3.0, path.costM, 1e-9);
    }

    @Test
    void unknownCellsAreTraversableAtTheirCost() {
        DijkstraPlanner p = planner(grid("????", "...."), 0, 3);
        goals.add(0, 1, 3.5, 1.5);
        assertTrue(p.plan(0.5, 0.5, goals, path));
        // Along the free row, then one step up into unknown: 3 + 3; beating 2 + a diagonal into unknown (3 sqrt2).
        assertEquals(6.0, path.costM, 1e-9);
        DijkstraPlanner allUnknown = planner(grid("????", "????"), 0, 3);
        assertTrue(allUnknown.plan(0.5, 1.5, goals, path));
        assertEquals(9.0, path.costM, 1e-9);
    }

    @Test
    void picksTheClosestGoalByPathNotByStraightLine() {
        DijkstraPlanner p = planner(grid(
                ".#....",
                ".#....",
                ".#....",
                "......"), 0, 2);
        goals.add(0, 1, 2.5, 3.5); // 2 m away in a straight line, behind the wall
        goals.add(1, 7, 0.5, 0.5); // 3 m away, in the open
        assertTrue(p.plan(0.5, 3.5, goals, path));
        assertEquals(7, path.goalId);
        assertEquals(1, path.requesterIndex);
        assertEquals(3.0, path.costM, 1e-9);
        goals.remove(1, 7);
        assertTrue(p.plan(0.5, 3.5, goals, path));
        assertEquals(1, path.goalId);
    }

    @Test
    void noGoalUnreachableOrOutsideGivesAnInvalidPath() {
        DijkstraPlanner p = planner(grid("..#..", "..#..", "..#.."), 0, 2);
        assertFalse(p.plan(0.5, 0.5, goals, path), "no goal");
        assertFalse(path.valid);
        goals.add(0, 1, 4.5, 0.5);
        assertFalse(p.plan(0.5, 0.5, goals, path), "walled off");
        assertFalse(path.valid);
        assertEquals(0, path.count());
        goals.add(0, 2, 40, 40);
        assertFalse(p.plan(0.5, 0.5, goals, path), "outside the map");
        assertFalse(p.plan(-3, 0.5, goals, path), "start outside the map");
    }

    @Test
    void longPathsAreSubsampledToTheCapacityKeepingBothEnds() {
        OccupancyGrid g = new OccupancyGrid(200);
        g.setGeometry(200, 1, 1.0, 0, 0);
        DijkstraPlanner p = new DijkstraPlanner(200, 0, 2);
        p.setMap(g);
        goals.add(0, 1, 199.5, 0.5);
        PlannedPath small = new PlannedPath(10);
        assertTrue(p.plan(0.5, 0.5, goals, small));
        assertEquals(10, small.count());
        assertEquals(0.5, small.xM[0]);
        assertEquals(199.5, small.xM[9]);
        assertEquals(199.0, small.costM, 1e-9);
        assertTrue(p.settledLastPlan() >= 200);
    }

    @Test
    void goalRegistryTagsGoalsByRequester() {
        assertTrue(goals.add(0, 1, 1, 1));
        assertTrue(goals.add(1, 1, 2, 2), "same id, other requester: another goal");
        assertFalse(goals.add(0, 1, 1, 1), "unchanged");
        assertTrue(goals.add(0, 1, 1.5, 1), "moved");
        assertEquals(2, goals.count());
        assertFalse(goals.remove(0, 9));
        assertTrue(goals.remove(0, 1));
        assertEquals(1, goals.count());
        assertEquals(1, goals.requester(0));
        GoalSet set = new GoalSet(4);
        set.add(5, 3, 3);
        set.add(6, 4, 4);
        assertTrue(goals.replace(0, set));
        assertEquals(3, goals.count());
        set.remove(5);
        assertTrue(goals.replace(0, set), "goal 5 removed by its requester");
        assertEquals(2, goals.count());
        assertFalse(goals.replace(0, set));
        assertEquals(1, goals.requester(0), "other requester's goal kept");
        assertEquals(6, goals.id(1));
    }
}
