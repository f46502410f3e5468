package io.rtaware.sim.actor;

/**
 * The outline of an actor, centred on its position: a circle or an axis-aligned box. Distances
 * and ray casts are exact. Immutable.
 */
public sealed interface ActorShape permits ActorShape.Circle, ActorShape.Box {

    /**
     * @param dxM x of a point relative to the centre, metres
     * @param dyM y of the point relative to the centre, metres
     * @return the distance from the point to the outline, metres; 0 inside
     */
    double clearanceM(double dxM, double dyM);

    /**
     * @param oxM ray origin x relative to the centre, metres
     * @param oyM ray origin y relative to the centre, metres
     * @param dirX x of the unit direction
     * @param dirY y of the unit direction
     * @return the distance along the ray to where it enters the outline (0 if the origin is
     *     inside), or {@link Double#POSITIVE_INFINITY} if it misses
     */
    double castM(double oxM, double oyM, double dirX, double dirY);

    /** @return the radius of the smallest circle around the centre that holds the outline, metres */
    double boundingRadiusM();

    /**
     * A circle (a person seen from above, a bin).
     *
     * @param radiusM radius, positive
     */
    record Circle(double radiusM) implements ActorShape {

        /**
         * @param radiusM radius, positive
         * @throws IllegalArgumentException if the radius is not positive and finite
         */
        public Circle {
            if (!(radiusM > 0) || Double.isInfinite(radiusM)) {
                throw new IllegalArgumentException("radius_m must be positive, got " + radiusM);
            }
        }

        @Override
        public double clearanceM(double dxM, double dyM) {
            return Math.max(0.0, Math.hypot(dxM, dyM) - radiusM);
        }

        @Override
        public double castM(double oxM, double oyM, double dirX, double dirY) {
            double c = oxM * oxM + oyM * oyM - radiusM * radiusM;
            if (c <= 0) {
                return 0.0;
            }
            double b = oxM * dirX + oyM * dirY;
            double disc = b * b - c;
            if (b >= 0 || disc < 0) {
                return Double.POSITIVE_INFINITY;
            }
            return -b - Math.sqrt(disc);
        }

        @Override
        public double boundingRadiusM() {
            return radiusM;
        }
    }

    /**
     * An axis-aligned box (a door leaf, a crate, a cart).
     *
     * @param widthM extent along x, positive
     * @param heightM extent along y, positive
     */
    record Box(double widthM, double heightM) implements ActorShape {

        /**
         * @param widthM extent along x, positive
         * @param heightM extent along y, positive
         * @throws IllegalArgumentException if a side is not positive and finite
         */
        public Box {
            if (!(widthM > 0) || Double.isInfinite(widthM) || !(heightM > 0) || Double.isInfinite(heightM)) {
                throw new IllegalArgumentException("size_m must be two positive numbers, got [" + widthM + ", " + heightM + "]");
            }
        }

        @Override
        public double clearanceM(double dxM, double dyM) {
            double ex = Math.max(0.0, Math.abs(dxM) - widthM / 2);
            double ey = Math.max(0.0, Math.abs(dyM) - heightM / 2);
            return Math.hypot(ex, ey);
        }

        @Override
        public double castM(double oxM, double oyM, double dirX, double dirY) {
            double hx = widthM / 2;
            double hy = heightM / 2;
            double tMin = 0.0;
            double tMax = Double.POSITIVE_INFINITY;
            if (dirX == 0) {
                if (Math.abs(oxM) > hx) {
                    return Double.POSITIVE_INFINITY;
                }
            } else {
                double t1 = (-hx - oxM) / dirX;
                double t2 = (hx - oxM) / dirX;
                tMin = Math.max(tMin, Math.min(t1, t2));
                tMax = Math.min(tMax, Math.max(t1, t2));
            }
            if (dirY == 0) {
                if (Math.abs(oyM) > hy) {
                    return Double.POSITIVE_INFINITY;
                }
            } else {
                double t1 = (-hy - oyM) / dirY;
                double t2 = (hy - oyM) / dirY;
                tMin = Math.max(tMin, Math.min(t1, t2));
                tMax = Math.min(tMax, Math.max(t1, t2));
            }
            return tMin <= tMax ? tMin : Double.POSITIVE_INFINITY;
        }

        @Override
        public double boundingRadiusM() {
            return Math.hypot(widthM / 2, heightM / 2);
        }
    }
}
