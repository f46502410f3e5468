package io.rtaware.sim.scenario;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.sim.actor.ActorSpec;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The {@code actors:} section of a scenario: the built-in moving scenarios, and one line naming the field and value for a malformed actor. */
class ActorScenarioTest {

    @TempDir
    Path dir;

    @Test
    void theBuiltInCorridorAndOfficeHaveTheirActors() {
        Scenario corridor = ScenarioLoader.load(ScenarioLoader.CORRIDOR);
        assertEquals(2, corridor.actors().size());
        assertTrue(corridor.actors().stream().allMatch(ActorSpec::moves), "people crossing");
        assertEquals(1.0, corridor.fastestActorMps(), 0.0);
        assertTrue(corridor.map().orElseThrow().isObstacleAt(6.0, -0.1), "the corridor's lower wall");
        assertTrue(!corridor.map().orElseThrow().isObstacleAt(4.0, -0.4), "a niche in the lower wall where a person waits");
        Scenario office = ScenarioLoader.load(ScenarioLoader.OFFICE);
        assertEquals(java.util.List.of(ActorSpec.Kind.BODY, ActorSpec.Kind.DOOR, ActorSpec.Kind.OBSTACLE),
                office.actors().stream().map(ActorSpec::kind).toList());
        assertEquals(1.8, office.actors().get(0).startWithinM(), 0.0, "the person steps out when the robot comes near");
        assertTrue(office.map().orElseThrow().isObstacleAt(5.5, 2.5), "the cabinet the person hides behind");
        assertEquals(0, ScenarioLoader.load(ScenarioLoader.PAPER_ROOM).actors().size(), "the paper's room stands still");
    }

    private String error(String actors) throws Exception {
        Path file = dir.resolve("s.yaml");
        Files.writeString(file, "start: {x: 1, y: 1}\nwaypoints: [{x: 2, y: 2}]\ngoal_tolerance_m: 0.3\ntime_limit_s: 60\n"
                + "actors:\n" + actors);
        ScenarioException e = assertThrows(ScenarioException.class, () -> ScenarioLoader.load(file));
        assertTrue(!e.getMessage().contains("\n"), "one line: " + e.getMessage());
        return e.getMessage();
    }

    @Test
    void aMalformedActorIsOneLineNamingTheFieldAndTheValue() throws Exception {
        assertTrue(error("  - {type: person, at: {x: 1, y: 1}}\n").contains("field 'actors[0].type' must be body or door or obstacle, got 'person'"),
                "unknown type");
        assertTrue(error("  - {type: body, path: [{x: 0, y: 0}, {x: 1, y: 0}], speed_mps: -1}\n")
                .contains("field 'actors[0].speed_mps' must be finite and not negative, got -1.0"), "negative speed");
        assertTrue(error("  - {type: body, path: [{x: 0, y: 0}, {x: 1, y: 0}]}\n").contains("field 'actors[0].speed_mps' is missing"),
                "a moving body needs a speed");
        assertTrue(error("  - {type: door, at: {x: 1, y: 1}, size_m: [1, 0.2]}\n").contains("field 'actors[0].close_at_s' is missing"),
                "a door needs its time");
        assertTrue(error("  - {type: obstacle, shape: box, size_m: [1], at: {x: 1, y: 1}, appear_at_s: 3}\n")
                .contains("field 'actors[0].size_m' must be [width, height] in metres, got [1]"), "box size");
        assertTrue(error("  - {type: body, shape: circle, radius_m: 0, at: {x: 1, y: 1}}\n")
                .contains("actors[0]: radius_m must be positive, got 0.0"), "radius");
        assertTrue(error("  - {type: body, at: {x: 1, y: 1}, colour: red}\n")
                .contains("field 'actors[0].colour' is not an actor field"), "unknown field");
        assertTrue(error("  - {type: body, path: [{x: 0, y: 0}, {x: 1, y: 0}], speed_mps: 1, repeat: forever}\n")
                .contains("field 'actors[0].repeat' must be once or loop or back_and_forth, got 'forever'"), "repeat");
        assertTrue(error("  - {name: a, at: {x: 1, y: 1}}\n  - {name: a, at: {x: 2, y: 1}}\n")
                .contains("field 'actors[1].name' repeats the name 'a'"), "names are unique");
    }

    /** Copies the paper's room (its map_server YAML and PGM) beside the scenario files the tests write. */
    private void paperRoomMap() throws Exception {
        for (String file : new String[] {"paper-room.yaml", "paper-room.pgm"}) {
            try (var in = ScenarioLoader.class.getResourceAsStream("/io/rtaware/sim/scenario/" + file)) {
                Files.copy(java.util.Objects.requireNonNull(in, file), dir.resolve(file));
            }
        }
    }

    private Scenario onThePaperRoom(String actors) throws Exception {
        Path file = dir.resolve("room.yaml");
        Files.writeString(file, "map: paper-room.yaml\nstart: {x: 1.0, y: 1.0}\nwaypoints: [{x: 3, y: 1}]\n"
                + "goal_tolerance_m: 0.3\ntime_limit_s: 60\nactors:\n" + actors);
        return ScenarioLoader.load(file);
    }

    private String refusedOnThePaperRoom(String actors) throws Exception {
        ScenarioException e = assertThrows(ScenarioException.class, () -> onThePaperRoom(actors));
        assertTrue(!e.getMessage().contains("\n"), "one line: " + e.getMessage());
        return e.getMessage();
    }

    /**
     * Issue 38: a path at 1e308, a speed of 1e308, an obstacle over the start and 20 000 actors all
     * loaded. Each is refused at load time in one line naming the bound.
     */
    @Test
    void actorsOutsideTheWorldTooFastTooManyOrOverTheStartAreRefused() throws Exception {
        paperRoomMap();
        assertTrue(refusedOnThePaperRoom("  - {type: body, path: [{x: 2, y: 2}, {x: 1.0e+308, y: 2}], speed_mps: 1}\n")
                .contains("field 'actors[0].path[1]' is (1.0E308, 2.0), outside the world: its map spans x -0.2..9.8 m, "
                        + "y -0.2..6.4 m"),
                "a path beyond the map");
        assertTrue(refusedOnThePaperRoom("  - {type: obstacle, at: {x: 2, y: -5}, size_m: [0.5, 0.5], appear_at_s: 1}\n")
                .contains("field 'actors[0].at' is (2.0, -5.0), outside the world"), "a point beyond the map");
        assertTrue(refusedOnThePaperRoom("  - {type: body, path: [{x: 2, y: 2}, {x: 3, y: 2}], speed_mps: 1.0e+308}\n")
                .contains("field 'actors[0].speed_mps' must be at most " + ActorSpec.MAX_SPEED_MPS + " m/s, got 1.0E308"),
                "a speed beyond the bound");
        assertTrue(refusedOnThePaperRoom("  - {name: crate, type: obstacle, at: {x: 1.1, y: 1.0}, size_m: [0.5, 0.5],"
                + " appear_at_s: 5}\n").contains("the start (1.0, 1.0) is inside actor 'crate' (actors[0]: obstacle at "
                + "(1.1, 1.0)): the robot's body (radius 0.2 m) would begin in a collision"), "an obstacle over the start");
        assertTrue(refusedOnThePaperRoom("  - {type: body, at: {x: 1.3, y: 1.0}}\n").contains("is inside actor 'body-1'"),
                "a body touching the robot's body at the start");
        String many = "  - {at: {x: 2, y: 2}}\n".repeat(20_000);
        assertTrue(refusedOnThePaperRoom(many).contains("field 'actors' has 20000 actors; a scenario may have at most "
                + Scenario.MAX_ACTORS), "20 000 actors");
        assertEquals(Scenario.MAX_ACTORS, onThePaperRoom("  - {at: {x: 2, y: 2}}\n".repeat(Scenario.MAX_ACTORS))
                .actors().size(), "the bound itself loads");
        assertEquals(1, onThePaperRoom("  - {type: body, at: {x: 1.5, y: 1.0}}\n").actors().size(),
                "a body that does not touch the robot at the start loads");
        assertTrue(error("  - {type: body, at: {x: 1.5, y: 1.0}}\n").contains("field 'actors' needs a 'map'"),
                "without a map there is no world for the actors");
    }
}
