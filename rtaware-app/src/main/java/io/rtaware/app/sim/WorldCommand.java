package io.rtaware.app.sim;

import io.rtaware.app.UserError;
import io.rtaware.app.output.OutputFile;
import io.rtaware.core.output.OutputWrites;
import io.rtaware.core.output.OutputFiles;
import io.rtaware.sim.render.WorldRenderer;
import io.rtaware.sim.scenario.Scenario;
import io.rtaware.sim.scenario.ScenarioException;
import io.rtaware.sim.scenario.ScenarioLoader;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/** {@code rtaware world}: draws a scenario (map, obstacles, start, waypoints, finish) to a PNG. */
@Command(name = "world", mixinStandardHelpOptions = true,
        description = {"Draw a scenario's map, start, waypoints and finish: the picture to check before a run.",
                "Example: rtaware world --scenario paper-room --png world.png"})
public final class WorldCommand implements Callable<Integer> {

    @Option(names = "--scenario", defaultValue = ScenarioLoader.PAPER_ROOM, paramLabel = "NAME|FILE",
            description = "A built-in scenario (" + ScenarioLoader.BUILT_IN_NAMES + ") or a scenario YAML file (default: ${DEFAULT-VALUE}).")
    String scenario;

    @Option(names = "--png", required = true, paramLabel = "FILE", description = "Where to write the picture.")
    Path png;

    @Override
    public Integer call() {
        OutputFile.of("--png", png);
        Scenario s;
        try {
            s = ScenarioLoader.load(scenario);
        } catch (ScenarioException e) {
            throw new UserError(e.getMessage());
        }
        if (s.map().isEmpty()) {
            throw new UserError("scenario '" + s.name() + "' has no map to draw");
        }
        OutputWrites writes = new OutputWrites(System.err);
        if (writes.writeFile(png, OutputFiles.png(new WorldRenderer().render(s, s.map().get(), List.of(), List.of())))) {
            System.out.println("world written to " + png);
        }
        return writes.exitStatus(0);
    }
}
