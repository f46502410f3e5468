package io.rtaware.sim.map;

/** Casts one laser beam: the distance to the first thing it hits. */
@FunctionalInterface
public interface BeamCaster {

    /**
     * @param xM ray origin x in metres
     * @param yM ray origin y in metres
     * @param dirX x of the unit direction
     * @param dirY y of the unit direction
     * @param maxRangeM the range beyond which nothing is looked for
     * @return distance in metres to the first thing hit; exactly {@code maxRangeM} if none is nearer
     */
    double castM(double xM, double yM, double dirX, double dirY, double maxRangeM);
}
