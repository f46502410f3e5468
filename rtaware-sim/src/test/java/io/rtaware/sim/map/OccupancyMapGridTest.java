package io.rtaware.sim.map;

import static org.junit.jupiter.api.Assertions.assertEquals;

import io.rtaware.robot.msg.OccupancyGrid;
import io.rtaware.sim.map.OccupancyMap.CellState;
import org.junit.jupiter.api.Test;

/** The simulator's walls as the robot's grid type: same geometry, obstacles occupied, the rest free. */
class OccupancyMapGridTest {

    @Test
    void obstaclesAreOccupiedAndTheRestFreeInTheSameGeometry() {
        CellState o = CellState.OCCUPIED;
        CellState f = CellState.FREE;
        OccupancyMap map = new OccupancyMap("test", 3, 2, 0.5, -1, 2, new CellState[] {o, f, f, f, f, o});

        OccupancyGrid grid = map.toGrid();

        assertEquals(3, grid.width());
        assertEquals(2, grid.height());
        assertEquals(0.5, grid.resolutionM);
        assertEquals(-1, grid.originXM);
        assertEquals(2, grid.originYM);
        byte[] expected = {OccupancyGrid.OCCUPIED, OccupancyGrid.FREE, OccupancyGrid.FREE,
            OccupancyGrid.FREE, OccupancyGrid.FREE, OccupancyGrid.OCCUPIED};
        for (int i = 0; i < expected.length; i++) {
            assertEquals(expected[i], grid.cells[i], "cell " + i);
        }
    }
}
