package io.rtaware.sim.scenario;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.dataformat.yaml.YAMLFactory;
import io.rtaware.core.text.NearestName;
import io.rtaware.robot.geometry.Point2d;
import io.rtaware.robot.geometry.Pose2d;
import io.rtaware.sim.actor.ActorShape;
import io.rtaware.sim.actor.ActorSpec;
import io.rtaware.sim.map.MapException;
import io.rtaware.sim.map.MapLoader;
import io.rtaware.sim.map.OccupancyMap;
import io.rtaware.sim.world.LaserTiming;
import io.rtaware.sim.world.RobotModel;
import java.io.FileNotFoundException;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.Set;
import java.util.Iterator;
import java.util.Map;
import java.util.List;
import java.util.Locale;
import java.util.Optional;

/**
 * Loads scenarios: {@link #load(String)} takes a built-in name ({@value #PAPER_ROOM}, {@value #CORRIDOR},
 * {@value #OFFICE}) or a
 * path to a YAML file with the fields {@code map} (optional, a map_server YAML relative to the
 * scenario file), {@code start: {x, y, yaw}}, {@code waypoints: [{x, y}, ...]},
 * {@code goal_tolerance_m}, {@code time_limit_s} and optionally {@code robot: {model: koala|ideal,
 * laser_link: usb|serial, PARAMETER: VALUE, ...}} (the robot model, its laser's link and overrides of its
 * numeric parameters, named as in {@link RobotModel#with(String, double)}) and {@code actors: [...]}
 * (what moves, closes or appears: {@link ActorSpec}; docs/moving-world.md gives the fields). Unknown top-level fields are ignored. Failures are a
 * {@link ScenarioException} with a one-line message naming the file, the field and the value.
 * Stateless and thread-safe.
 */
public final class ScenarioLoader {

    /** The built-in scenario: the paper's experiment room. */
    public static final String PAPER_ROOM = "paper-room";
    /** The built-in corridor where people cross (issue 27). */
    public static final String CORRIDOR = "corridor";
    /** The built-in office: a person steps out from behind a corner, a door closes, a box appears (issue 27). */
    public static final String OFFICE = "office";
    /** Every built-in scenario's name. */
    public static final List<String> BUILT_IN = List.of(PAPER_ROOM, CORRIDOR, OFFICE);
    /** The built-in scenarios' names as a help text lists them (a constant, for annotations). */
    public static final String BUILT_IN_NAMES = PAPER_ROOM + ", " + CORRIDOR + ", " + OFFICE;

    private static final String RESOURCE_DIR = "/io/rtaware/sim/scenario/";
    private static final ObjectMapper YAML = new ObjectMapper(new YAMLFactory());

    private ScenarioLoader() {
    }

    /**
     * @param nameOrPath a built-in name ({@link #BUILT_IN}) or a path to a scenario YAML file
     * @return the scenario, with its map loaded
     * @throws ScenarioException if the file is missing or malformed, or a name that is neither a
     *     built-in scenario nor a file is given (the message suggests the nearest built-in name)
     */
    public static Scenario load(String nameOrPath) {
        if (BUILT_IN.contains(nameOrPath)) {
            return builtIn(nameOrPath);
        }
        try {
            Path file = Path.of(nameOrPath);
            if (!Files.exists(file) && file.getNameCount() == 1 && !nameOrPath.matches("(?i).*\\.ya?ml")) {
                throw new ScenarioException("unknown scenario '" + nameOrPath + "'" + NearestName.suggestion(nameOrPath,
                        BUILT_IN) + " (built-in scenarios: " + BUILT_IN_NAMES + "; or give a scenario YAML file)");
            }
            return load(file);
        } catch (InvalidPathException e) {
            throw new ScenarioException("scenario '" + nameOrPath + "' is not a file name this system can use ("
                    + e.getReason() + "); the JVM reads file names in the locale's encoding, so with LC_ALL=C only ASCII "
                    + "names work: use a UTF-8 locale (LC_ALL=C.UTF-8) or an ASCII path");
        }
    }

    /**
     * @param file a scenario YAML file
     * @return the scenario, with its map loaded
     * @throws ScenarioException if the file is missing or malformed
     */
    public static Scenario load(Path file) {
        String name = file.getFileName().toString().replaceFirst("\\.(ya?ml)$", "");
        Path dir = file.toAbsolutePath().getParent();
        try (InputStream in = Files.newInputStream(file)) {
            return parse(file.toString(), name, in, map -> MapLoader.load(dir.resolve(map)));
        } catch (NoSuchFileException e) {
            throw new ScenarioException(file + ": file not found");
        } catch (IOException e) {
            throw new ScenarioException(file + ": cannot read: " + e.getMessage(), e);
        }
    }

    /**
     * @param name the built-in scenario's name
     * @return the built-in scenario
     * @throws ScenarioException if there is no built-in scenario of that name
     */
    public static Scenario builtIn(String name) {
        if (!BUILT_IN.contains(name)) {
            throw new ScenarioException("built-in scenarios: " + String.join(", ", BUILT_IN) + "; got '" + name + "'");
        }
        String resource = RESOURCE_DIR + name + ".scenario.yaml";
        try (InputStream in = open(resource)) {
            return parse("classpath:" + resource, name, in, ScenarioLoader::loadMapResource);
        } catch (IOException e) {
            throw new ScenarioException("classpath:" + resource + ": cannot read: " + e.getMessage(), e);
        }
    }

    private static OccupancyMap loadMapResource(String mapName) {
        String resource = RESOURCE_DIR + mapName;
        try (InputStream in = open(resource)) {
            return MapLoader.load("classpath:" + resource, in, image -> open(RESOURCE_DIR + image));
        } catch (IOException e) {
            throw new MapException("classpath:" + resource + ": cannot read: " + e.getMessage(), e);
        }
    }

    private static InputStream open(String resource) throws IOException {
        InputStream in = ScenarioLoader.class.getResourceAsStream(resource);
        if (in == null) {
            throw new FileNotFoundException("missing resource " + resource);
        }
        return in;
    }

    @FunctionalInterface
    private interface MapResolver {
        OccupancyMap load(String mapField);
    }

    private static Scenario parse(String source, String name, InputStream in, MapResolver maps) {
        JsonNode root;
        try {
            root = YAML.readTree(in);
        } catch (IOException e) {
            String msg = e.getMessage() == null ? "" : e.getMessage().replaceAll("\\s*\\R\\s*", " ").trim();
            throw new ScenarioException(source + ": not valid YAML: " + msg, e);
        }
        if (root == null || !root.isObject()) {
            throw new ScenarioException(source + ": expected a YAML mapping, got " + root);
        }
        Optional<OccupancyMap> map = Optional.empty();
        JsonNode mapNode = root.get("map");
        if (mapNode != null && !mapNode.isNull()) {
            if (!mapNode.isTextual() || mapNode.asText().isBlank()) {
                throw new ScenarioException(source + ": field 'map' must be a file name, got " + mapNode);
            }
            try {
                map = Optional.of(maps.load(mapNode.asText()));
            } catch (MapException e) {
                throw new ScenarioException(source + ": field 'map' (" + mapNode.asText() + "): " + e.getMessage(), e);
            } catch (InvalidPathException e) {
                throw new ScenarioException(source + ": field 'map' is not a file name this system can use ("
                        + e.getReason() + "; with LC_ALL=C only ASCII names work), got " + mapNode.asText());
            }
        }
        JsonNode startNode = required(source, root, "start");
        Pose2d start = new Pose2d(number(source, startNode, "start.x", "x"),
                number(source, startNode, "start.y", "y"),
                startNode.has("yaw") ? number(source, startNode, "start.yaw", "yaw") : 0.0);
        JsonNode wpNode = required(source, root, "waypoints");
        if (!wpNode.isArray() || wpNode.isEmpty()) {
            throw new ScenarioException(source + ": field 'waypoints' must be a non-empty list of {x, y}, got " + wpNode);
        }
        List<Point2d> waypoints = new ArrayList<>();
        for (int i = 0; i < wpNode.size(); i++) {
            JsonNode wp = wpNode.get(i);
            String field = "waypoints[" + i + "]";
            if (!wp.isObject()) {
                throw new ScenarioException(source + ": field '" + field + "' must be {x, y}, got " + wp);
            }
            waypoints.add(new Point2d(number(source, wp, field + ".x", "x"), number(source, wp, field + ".y", "y")));
        }
        double tolerance = number(source, root, "goal_tolerance_m", "goal_tolerance_m");
        if (!(tolerance > 0)) {
            throw new ScenarioException(source + ": field 'goal_tolerance_m' must be positive, got " + tolerance);
        }
        double limit = number(source, root, "time_limit_s", "time_limit_s");
        if (!(limit > 0)) {
            throw new ScenarioException(source + ": field 'time_limit_s' must be positive, got " + limit);
        }
        Optional<RobotModel> robot = robot(source, root.get("robot"));
        List<ActorSpec> actors = actors(source, root.get("actors"));
        if (!actors.isEmpty()) {
            checkActorsInTheWorld(source, map, actors);
            checkStartIsClear(source, start, robot.orElse(RobotModel.koala(RobotModel.PAPER_TOP_SPEED_MPS)), actors);
        }
        return new Scenario(name, map, start, waypoints, tolerance, limit, robot, actors);
    }

    /**
     * Every actor's points lie in the world, whose extent is its map's: actors live in the
     * simulated world, so a scenario without a map has none.
     */
    private static void checkActorsInTheWorld(String source, Optional<OccupancyMap> map, List<ActorSpec> actors) {
        if (map.isEmpty()) {
            throw new ScenarioException(source + ": field 'actors' needs a 'map': actors move in the simulated world, "
                    + "whose extent is its map's");
        }
        OccupancyMap m = map.get();
        double minX = m.originXM();
        double minY = m.originYM();
        double maxX = minX + m.widthM();
        double maxY = minY + m.heightM();
        for (int i = 0; i < actors.size(); i++) {
            List<Point2d> path = actors.get(i).path();
            for (int k = 0; k < path.size(); k++) {
                Point2d p = path.get(k);
                if (p.xM() < minX || p.xM() > maxX || p.yM() < minY || p.yM() > maxY) {
                    throw new ScenarioException(String.format(Locale.ROOT, "%s: field 'actors[%d].%s' is (%s, %s), outside "
                            + "the world: its map spans x %s..%s m, y %s..%s m", source, i,
                            path.size() == 1 ? "at" : "path[" + k + "]", p.xM(), p.yM(), metres(minX), metres(maxX),
                            metres(minY), metres(maxY)));
                }
            }
        }
    }

    /** @return a map coordinate to the millimetre, without trailing zeros */
    private static String metres(double m) {
        return String.format(Locale.ROOT, "%.3f", m).replaceFirst("\\.?0+$", "");
    }

    /**
     * No actor stands where the robot starts: where a body waits before it moves, where a door
     * closes or an obstacle appears must not overlap the robot's body at the start.
     */
    private static void checkStartIsClear(String source, Pose2d start, RobotModel robot, List<ActorSpec> actors) {
        double radiusM = robot.body().radiusM();
        for (int i = 0; i < actors.size(); i++) {
            ActorSpec a = actors.get(i);
            Point2d at = a.path().get(0);
            if (a.shape().clearanceM(start.xM() - at.xM(), start.yM() - at.yM()) < radiusM) {
                throw new ScenarioException(String.format(Locale.ROOT, "%s: the start (%s, %s) is inside actor '%s' "
                        + "(actors[%d]: %s at (%s, %s)): the robot's body (radius %s m) would begin in a collision; move "
                        + "the start or the actor", source, start.xM(), start.yM(), a.name(), i, a.kind().yamlName(),
                        at.xM(), at.yM(), radiusM));
            }
        }
    }

    private static final Set<String> ACTOR_FIELDS = Set.of("name", "type", "shape", "radius_m", "size_m", "path", "at",
            "speed_mps", "repeat", "start_at_s", "start_when_robot_within_m", "start_jitter_s", "close_at_s",
            "appear_at_s");

    private static List<ActorSpec> actors(String source, JsonNode node) {
        if (node == null || node.isNull()) {
            return List.of();
        }
        if (!node.isArray()) {
            throw new ScenarioException(source + ": field 'actors' must be a list, got " + node);
        }
        if (node.size() > Scenario.MAX_ACTORS) {
            throw new ScenarioException(source + ": field 'actors' has " + node.size() + " actors; a scenario may have at most "
                    + Scenario.MAX_ACTORS);
        }
        List<ActorSpec> actors = new ArrayList<>();
        Set<String> names = new HashSet<>();
        for (int i = 0; i < node.size(); i++) {
            JsonNode a = node.get(i);
            String at = "actors[" + i + "]";
            if (!a.isObject()) {
                throw new ScenarioException(source + ": field '" + at + "' must be a mapping, got " + a);
            }
            for (Iterator<String> it = a.fieldNames(); it.hasNext(); ) {
                String f = it.next();
                if (!ACTOR_FIELDS.contains(f)) {
                    throw new ScenarioException(source + ": field '" + at + "." + f + "' is not an actor field (known: "
                            + String.join(", ", new java.util.TreeSet<>(ACTOR_FIELDS)) + ")");
                }
            }
            ActorSpec.Kind kind = choice(source, a, at + ".type", "type", "body", ActorSpec.Kind.class);
            String actorName = a.has("name") ? a.get("name").asText() : kind.yamlName() + "-" + (i + 1);
            if (!names.add(actorName)) {
                throw new ScenarioException(source + ": field '" + at + ".name' repeats the name '" + actorName + "'");
            }
            String shapeName = kind == ActorSpec.Kind.BODY ? "circle" : "box";
            ActorShape shape;
            try {
                shape = switch (text(source, a, at + ".shape", "shape", shapeName)) {
                    case "circle" -> new ActorShape.Circle(optional(source, a, at + ".radius_m", "radius_m", 0.25));
                    case "box" -> box(source, a, at);
                    default -> throw new ScenarioException(source + ": field '" + at + ".shape' must be circle or box, got "
                            + a.get("shape"));
                };
            } catch (IllegalArgumentException e) {
                throw new ScenarioException(source + ": " + at + ": " + e.getMessage(), e);
            }
            List<Point2d> path = new ArrayList<>();
            JsonNode pathNode = a.get("path");
            JsonNode atNode = a.get("at");
            if (pathNode != null && atNode != null) {
                throw new ScenarioException(source + ": field '" + at + "' has both 'path' and 'at'; give one");
            }
            if (atNode != null) {
                path.add(new Point2d(number(source, atNode, at + ".at.x", "x"), number(source, atNode, at + ".at.y", "y")));
            } else if (pathNode != null) {
                if (!pathNode.isArray() || pathNode.isEmpty()) {
                    throw new ScenarioException(source + ": field '" + at + ".path' must be a non-empty list of {x, y}, got "
                            + pathNode);
                }
                for (int k = 0; k < pathNode.size(); k++) {
                    String pf = at + ".path[" + k + "]";
                    path.add(new Point2d(number(source, pathNode.get(k), pf + ".x", "x"),
                            number(source, pathNode.get(k), pf + ".y", "y")));
                }
            } else {
                throw new ScenarioException(source + ": field '" + at + ".path' (or '" + at + ".at') is missing");
            }
            double appear = switch (kind) {
                case DOOR -> number(source, a, at + ".close_at_s", "close_at_s");
                case OBSTACLE -> number(source, a, at + ".appear_at_s", "appear_at_s");
                case BODY -> optional(source, a, at + ".appear_at_s", "appear_at_s", 0.0);
            };
            if (kind != ActorSpec.Kind.BODY && path.size() != 1) {
                throw new ScenarioException(source + ": field '" + at + ".at' must be one point for a " + kind.yamlName()
                        + ", got a path of " + path.size());
            }
            if (kind == ActorSpec.Kind.BODY && path.size() > 1 && !a.has("speed_mps")) {
                throw new ScenarioException(source + ": field '" + at + ".speed_mps' is missing");
            }
            try {
                actors.add(new ActorSpec(actorName, kind, shape, path,
                        optional(source, a, at + ".speed_mps", "speed_mps", 0.0),
                        choice(source, a, at + ".repeat", "repeat", "once", ActorSpec.Repeat.class),
                        optional(source, a, at + ".start_at_s", "start_at_s", 0.0),
                        optional(source, a, at + ".start_when_robot_within_m", "start_when_robot_within_m", 0.0),
                        optional(source, a, at + ".start_jitter_s", "start_jitter_s", 0.0), appear));
            } catch (IllegalArgumentException e) {
                String m = e.getMessage();
                int space = m.indexOf(' ');
                throw new ScenarioException(source + ": field '" + at + "." + m.substring(0, space) + "'" + m.substring(space), e);
            }
        }
        return actors;
    }

    private static ActorShape box(String source, JsonNode a, String at) {
        JsonNode size = a.get("size_m");
        if (size == null || !size.isArray() || size.size() != 2 || !size.get(0).isNumber() || !size.get(1).isNumber()) {
            throw new ScenarioException(source + ": field '" + at + ".size_m' must be [width, height] in metres, got " + size);
        }
        return new ActorShape.Box(size.get(0).asDouble(), size.get(1).asDouble());
    }

    private static String text(String source, JsonNode parent, String path, String field, String orElse) {
        JsonNode n = parent.get(field);
        if (n == null || n.isNull()) {
            return orElse;
        }
        if (!n.isTextual()) {
            throw new ScenarioException(source + ": field '" + path + "' must be a word, got " + n);
        }
        return n.asText();
    }

    private static <E extends Enum<E>> E choice(String source, JsonNode parent, String path, String field, String orElse,
                                                Class<E> type) {
        String value = text(source, parent, path, field, orElse);
        for (E e : type.getEnumConstants()) {
            if (e.name().equalsIgnoreCase(value)) {
                return e;
            }
        }
        List<String> known = new ArrayList<>();
        for (E e : type.getEnumConstants()) {
            known.add(e.name().toLowerCase(java.util.Locale.ROOT));
        }
        throw new ScenarioException(source + ": field '" + path + "' must be " + String.join(" or ", known) + ", got '"
                + value + "'");
    }

    private static double optional(String source, JsonNode parent, String path, String field, double orElse) {
        JsonNode n = parent.get(field);
        return n == null || n.isNull() ? orElse : number(source, parent, path, field);
    }

    private static Optional<RobotModel> robot(String source, JsonNode node) {
        if (node == null || node.isNull()) {
            return Optional.empty();
        }
        if (!node.isObject()) {
            throw new ScenarioException(source + ": field 'robot' must be a mapping {model: koala|ideal, ...}, got " + node);
        }
        JsonNode modelNode = node.get("model");
        String modelName = modelNode == null ? RobotModel.KOALA_NAME : modelNode.asText();
        RobotModel model;
        try {
            model = RobotModel.named(modelName, RobotModel.PAPER_TOP_SPEED_MPS);
        } catch (IllegalArgumentException e) {
            throw new ScenarioException(source + ": field 'robot.model': " + e.getMessage(), e);
        }
        for (Iterator<Map.Entry<String, JsonNode>> it = node.fields(); it.hasNext(); ) {
            Map.Entry<String, JsonNode> f = it.next();
            if (f.getKey().equals("model")) {
                continue;
            }
            if (f.getKey().equals("laser_link")) {
                try {
                    model = model.withLaserLink(LaserTiming.Link.parse(f.getValue().asText()));
                } catch (IllegalArgumentException e) {
                    throw new ScenarioException(source + ": field 'robot.laser_link': " + e.getMessage(), e);
                }
                continue;
            }
            double v = number(source, node, "robot." + f.getKey(), f.getKey());
            try {
                model = model.with(f.getKey(), v);
            } catch (IllegalArgumentException e) {
                throw new ScenarioException(source + ": field 'robot." + f.getKey() + "': " + e.getMessage(), e);
            }
        }
        return Optional.of(model);
    }

    private static JsonNode required(String source, JsonNode parent, String field) {
        JsonNode n = parent.get(field);
        if (n == null || n.isNull()) {
            throw new ScenarioException(source + ": field '" + field + "' is missing");
        }
        return n;
    }

    private static double number(String source, JsonNode parent, String path, String field) {
        if (!parent.isObject()) {
            throw new ScenarioException(source + ": field '" + path + "' needs a mapping, got " + parent);
        }
        JsonNode n = parent.get(field);
        if (n == null || n.isNull()) {
            throw new ScenarioException(source + ": field '" + path + "' is missing");
        }
        if (!n.isNumber() || !Double.isFinite(n.asDouble())) {
            throw new ScenarioException(source + ": field '" + path + "' must be a finite number, got " + n);
        }
        return n.asDouble();
    }
}
