package io.rtaware.core.monitor;

import io.rtaware.core.data.Key;
import io.rtaware.core.data.StateValue;
import io.rtaware.core.data.StateVariable;
import io.rtaware.core.task.Schedule;
import io.rtaware.core.task.TaskSpec;
import io.rtaware.core.time.Durations;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * Verifies what the tasks declared at initialization and, if all is well, builds the data graph:
 * unique non-empty names, valid schedules, exactly one producer per key, every consumed key
 * produced with the same type. Every violation is collected, so one
 * {@link ConfigurationException} lists them all. Then one {@link StateVariable} is created per
 * produced key and every task's handles are bound to it. Stateless.
 */
final class GraphValidator {

    private GraphValidator() {
    }

    /**
     * @param tasks every task's declarations, in registration order, after its initialization
     *     (a task whose {@code initialize} threw has that as its first violation)
     * @return the data graph, with every handle bound
     * @throws ConfigurationException listing every violation found
     */
    static DataGraph validateAndBind(List<DeclaringSetup> tasks) {
        List<String> violations = new ArrayList<>();
        Map<String, Integer> seen = new LinkedHashMap<>();
        for (DeclaringSetup task : tasks) {
            TaskSpec spec = task.spec;
            if (seen.merge(spec.name(), 1, Integer::sum) == 2) {
                violations.add("task name '" + spec.name() + "' is used by more than one task; names must be unique");
            }
            if (spec.name().isBlank()) {
                violations.add("a task has an empty name");
            }
            checkSchedule(spec, violations);
        }
        tasks.forEach(t -> violations.addAll(t.violations));

        // Declaration order: error messages list produced keys as the tasks declared them.
        Map<String, DeclaringSetup> producerOf = new LinkedHashMap<>();
        Map<String, Key<?>> producedKey = new LinkedHashMap<>();
        for (DeclaringSetup task : tasks) {
            for (OutputHandle<?> out : task.outputs) {
                String key = out.key().name();
                DeclaringSetup other = producerOf.get(key);
                if (other == task) {
                    continue; // declared twice by one task: already reported by its declarations
                }
                if (other != null) {
                    violations.add("key '" + key + "' is produced by tasks '" + other.spec.name() + "' and '"
                            + task.spec.name() + "'; a key has exactly one producer");
                } else {
                    producerOf.put(key, task);
                    producedKey.put(key, out.key());
                }
            }
        }
        Map<String, List<String>> consumersOf = new TreeMap<>();
        for (DeclaringSetup task : tasks) {
            for (InputHandle<?> in : task.inputs) {
                String key = in.key().name();
                Key<?> produced = producedKey.get(key);
                if (produced == null) {
                    violations.add("task '" + task.spec.name() + "' consumes '" + key
                            + "' but no task produces it; produced keys: "
                            + (producedKey.isEmpty() ? "(none)" : String.join(", ", producedKey.keySet())));
                } else if (!produced.type().equals(in.key().type())) {
                    violations.add("task '" + task.spec.name() + "' consumes '" + key + "' as "
                            + in.key().type().getSimpleName() + " but task '" + producerOf.get(key).spec.name()
                            + "' produces it as " + produced.type().getSimpleName());
                }
                consumersOf.computeIfAbsent(key, k -> new ArrayList<>()).add(task.spec.name());
            }
        }
        if (!violations.isEmpty()) {
            throw new ConfigurationException(violations);
        }

        List<StateVariable<?>> variables = new ArrayList<>();
        Map<String, String> producers = new LinkedHashMap<>();
        for (Map.Entry<String, Key<?>> entry : producedKey.entrySet()) {
            variables.add(newVariable(entry.getValue()));
            producers.put(entry.getKey(), producerOf.get(entry.getKey()).spec.name());
        }
        DataGraph graph = new DataGraph(variables, producers, consumersOf);
        for (DeclaringSetup task : tasks) {
            for (OutputHandle<?> out : task.outputs) {
                String key = out.key().name();
                out.bind(graph.variable(key), graph.indexOf(key));
            }
            for (InputHandle<?> in : task.inputs) {
                in.bind(graph.variable(in.key().name()));
            }
        }
        return graph;
    }

    private static <T extends StateValue<T>> StateVariable<T> newVariable(Key<T> key) {
        return new StateVariable<>(key);
    }

    private static void checkSchedule(TaskSpec spec, List<String> violations) {
        String task = "task '" + spec.name() + "'";
        if (spec.schedule() instanceof Schedule.Periodic p) {
            if (p.periodNs() <= 0) {
                violations.add(task + " has period " + Durations.format(p.periodNs()) + "; a period must be positive");
            } else if (p.deadlineNs() <= 0 || p.deadlineNs() > p.periodNs()) {
                violations.add(task + " has deadline " + Durations.format(p.deadlineNs())
                        + "; it must be positive and at most the period " + Durations.format(p.periodNs()));
            }
            if (p.isAdaptive() && p.periodNs() > 0
                    && (p.minPeriodNs() <= 0 || p.minPeriodNs() > p.periodNs() || p.periodNs() > p.maxPeriodNs())) {
                violations.add(task + " has period range " + Durations.format(p.minPeriodNs()) + ".."
                        + Durations.format(p.maxPeriodNs()) + " and period " + Durations.format(p.periodNs())
                        + "; it needs 0 < min <= period <= max");
            }
            if (p.offsetNs() < 0) {
                violations.add(task + " has offset " + Durations.format(p.offsetNs()) + "; an offset cannot be negative");
            }
        } else if (spec.schedule() instanceof Schedule.Once o && o.offsetNs() < 0) {
            violations.add(task + " has offset " + Durations.format(o.offsetNs()) + "; an offset cannot be negative");
        }
    }
}
