package io.rtaware.experiment.report;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * The ground-truth path of one run and the path the robot believed it drove, from its
 * {@code trajectory.csv} (header {@code t_s,x_m,y_m,yaw_rad}, then, from the version that
 * records it, {@code odom_x_m,odom_y_m,odom_yaw_rad}).
 *
 * @param set the run's set number
 * @param run the run's number
 * @param xM x of each sample, m
 * @param yM y of each sample, m
 * @param believedXM x of the robot's own estimate (odometry) at each sample that has one, m;
 *     empty for a file without it
 * @param believedYM y of the robot's own estimate, m
 */
public record Trajectory(int set, int run, double[] xM, double[] yM, double[] believedXM, double[] believedYM) {

    /** The file name inside a run's folder. */
    public static final String FILE_NAME = "trajectory.csv";

    /** Most points kept per path; longer paths are thinned evenly (the last point is kept). */
    static final int MAX_POINTS = 2_000;

    /**
     * @param file a trajectory.csv
     * @param set the run's set number
     * @param run the run's number
     * @return the path
     * @throws IOException if the file cannot be read or its header is not {@code t_s,x_m,y_m,yaw_rad}
     */
    public static Trajectory read(Path file, int set, int run) throws IOException {
        List<String> lines = Files.readAllLines(file);
        if (lines.isEmpty() || !lines.get(0).strip().startsWith("t_s,x_m,y_m")) {
            throw new IOException(file + ": expected header t_s,x_m,y_m,yaw_rad");
        }
        List<double[]> points = new ArrayList<>();
        List<double[]> believed = new ArrayList<>();
        for (String line : lines.subList(1, lines.size())) {
            String[] f = line.split(",", -1);
            if (f.length < 3) {
                continue;
            }
            try {
                double x = Double.parseDouble(f[1]);
                double y = Double.parseDouble(f[2]);
                if (Double.isFinite(x) && Double.isFinite(y)) {
                    points.add(new double[] {x, y}); // a pose the run did not have (NaN) is no point of the path
                }
                if (f.length >= 6 && !f[4].isEmpty() && !f[5].isEmpty()) {
                    double bx = Double.parseDouble(f[4]);
                    double by = Double.parseDouble(f[5]);
                    if (Double.isFinite(bx) && Double.isFinite(by)) {
                        believed.add(new double[] {bx, by});
                    }
                }
            } catch (NumberFormatException e) {
                throw new IOException(file + ": not a number in line '" + line + "'", e);
            }
        }
        List<double[]> keptBelieved = thin(believed);
        List<double[]> kept = thin(points);
        return new Trajectory(set, run, kept.stream().mapToDouble(p -> p[0]).toArray(),
                kept.stream().mapToDouble(p -> p[1]).toArray(), keptBelieved.stream().mapToDouble(p -> p[0]).toArray(),
                keptBelieved.stream().mapToDouble(p -> p[1]).toArray());
    }

    private static List<double[]> thin(List<double[]> points) {
        int stride = Math.max(1, (points.size() + MAX_POINTS - 1) / MAX_POINTS);
        List<double[]> kept = new ArrayList<>();
        for (int i = 0; i < points.size(); i += stride) {
            kept.add(points.get(i));
        }
        if (!points.isEmpty() && kept.get(kept.size() - 1) != points.get(points.size() - 1)) {
            kept.add(points.get(points.size() - 1));
        }
        return kept;
    }

    /** @return the rectangle holding the path, or null if it has fewer than two distinct points */
    public WorldBounds bounds() {
        if (xM.length == 0) {
            return null;
        }
        double minX = java.util.Arrays.stream(xM).min().getAsDouble();
        double maxX = java.util.Arrays.stream(xM).max().getAsDouble();
        double minY = java.util.Arrays.stream(yM).min().getAsDouble();
        double maxY = java.util.Arrays.stream(yM).max().getAsDouble();
        if (maxX <= minX || maxY <= minY) {
            return null;
        }
        return new WorldBounds(minX, minY, maxX, maxY);
    }
}
