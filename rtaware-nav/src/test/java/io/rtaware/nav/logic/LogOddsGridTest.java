package io.rtaware.nav.logic;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.robot.msg.LaserScan;
import io.rtaware.robot.msg.OccupancyGrid;
import org.junit.jupiter.api.Test;

class LogOddsGridTest {

    private final LogOddsGrid grid = new LogOddsGrid(0, 0, 20, 20, 0.05);

    @Test
    void beamClearsCellsBeforeTheHitMarksTheHitAndLeavesBeyondUnchanged() {
        grid.integrateBeam(0.025, 0.025, 0.0, 0.5, true);
        for (int x = 0; x < 10; x++) {
            assertEquals(OccupancyGrid.FREE, grid.state(x, 0), "cell " + x);
        }
        assertEquals(OccupancyGrid.OCCUPIED, grid.state(10, 0));
        for (int x = 11; x < 20; x++) {
            assertEquals(OccupancyGrid.UNKNOWN, grid.state(x, 0), "cell " + x);
            assertEquals(0f, grid.logOdds(x, 0));
        }
        assertEquals(OccupancyGrid.UNKNOWN, grid.state(0, 1), "cells beside the beam untouched");
    }

    @Test
    void diagonalBeamTracesBresenhamCells() {
        grid.integrateBeam(0.025, 0.025, Math.PI / 4, Math.hypot(0.25, 0.25), true);
        for (int i = 0; i < 5; i++) {
            assertEquals(OccupancyGrid.FREE, grid.state(i, i), "cell " + i);
        }
        assertEquals(OccupancyGrid.OCCUPIED, grid.state(5, 5));
        assertEquals(OccupancyGrid.UNKNOWN, grid.state(6, 6));
    }

    @Test
    void noHitBeamClearsToItsEndAndMarksNothing() {
        grid.integrateBeam(0.025, 0.025, Math.PI / 2, 0.3, false);
        for (int y = 0; y <= 6; y++) {
            assertEquals(OccupancyGrid.FREE, grid.state(0, y), "cell " + y);
        }
        assertEquals(OccupancyGrid.UNKNOWN, grid.state(0, 7));
    }

    @Test
    void repeatedMissesTurnAnOccupiedCellBackToFreeAndLogOddsAreClamped() {
        grid.integrateBeam(0.025, 0.025, 0.0, 0.5, true);
        for (int i = 0; i < 20; i++) {
            grid.integrateBeam(0.025, 0.025, 0.0, 0.5, true);
        }
        assertEquals(LogOddsGrid.CLAMP_LOG_ODDS, grid.logOdds(10, 0));
        for (int i = 0; i < 30; i++) {
            grid.integrateBeam(0.025, 0.025, 0.0, 0.8, true);
        }
        assertEquals(OccupancyGrid.FREE, grid.state(10, 0));
        assertEquals(OccupancyGrid.OCCUPIED, grid.state(16, 0));
    }

    @Test
    void scanHitsWinOverGrazingMissesAndOutOfRangeBeamsMarkNoHit() {
        LaserScan scan = new LaserScan(3);
        scan.setCount(3);
        scan.minAngleRad = -0.01;
        scan.maxAngleRad = 0.01;
        scan.maxRangeM = 0.6;
        scan.rangesM[0] = 0.8f; // beyond max range: clears to 0.6 m
        scan.rangesM[1] = 0.5f; // hit at cell 10
        scan.rangesM[2] = Float.NaN; // ignored
        grid.integrate(scan, 0.025, 0.025, 0.0);
        assertEquals(OccupancyGrid.OCCUPIED, grid.state(10, 0), "the hit survives the other beam crossing it");
        assertEquals(OccupancyGrid.FREE, grid.state(11, 0));
        assertEquals(1, grid.scansIntegrated());
        OccupancyGrid out = new OccupancyGrid(400);
        grid.exportTo(out);
        assertEquals(20, out.width());
        assertEquals(OccupancyGrid.OCCUPIED, out.cell(10, 0));
        assertEquals(10, out.cellX(0.52));
        assertTrue(out.centerXM(10) > 0.5 && out.centerXM(10) < 0.55);
    }

    @Test
    void aReadingTooCloseToMeasureIsAHitAtTheMinimumRange() {
        LaserScan scan = new LaserScan(2);
        scan.setCount(2);
        scan.minAngleRad = 0.0;
        scan.maxAngleRad = Math.PI / 2;
        scan.maxRangeM = 0.6;
        scan.minRangeM = 0.3;
        scan.rangesM[0] = Float.NEGATIVE_INFINITY; // along x: an obstacle at 0.3 m, cell 6
        scan.rangesM[1] = 0f;                      // along y: the same
        grid.integrate(scan, 0.025, 0.025, 0.0);
        assertEquals(OccupancyGrid.OCCUPIED, grid.state(6, 0), "-Inf marks the cell at the minimum range");
        assertEquals(OccupancyGrid.OCCUPIED, grid.state(0, 6), "0 m marks the cell at the minimum range");
        assertEquals(OccupancyGrid.UNKNOWN, grid.state(7, 0), "nothing is known beyond it");
    }

    @Test
    void beamsLeavingTheGridAreClipped() {
        grid.integrateBeam(0.975, 0.025, 0.0, 3.0, true);
        assertEquals(OccupancyGrid.FREE, grid.state(19, 0));
        grid.integrateBeam(-1.0, 0.025, 0.0, 1.5, true);
        assertEquals(OccupancyGrid.OCCUPIED, grid.state(10, 0));
        assertEquals(OccupancyGrid.FREE, grid.state(0, 0));
    }
}
