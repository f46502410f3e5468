package io.rtaware.core.monitor;

import io.rtaware.core.data.Key;
import io.rtaware.core.data.StateValue;
import io.rtaware.core.data.StateVariable;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The verified data graph of a monitor: one {@link StateVariable} per produced key, its producer
 * and its consumers, and the queries observers ask of it. Immutable after construction (the
 * variables themselves are the live store). Thread-safe.
 */
final class DataGraph {

    private final List<StateVariable<?>> variables;
    private final Map<String, StateVariable<?>> byName;
    private final Map<String, String> producers;
    private final Map<String, List<String>> consumers;
    private final List<String> keyNames;
    /**
     * Key index by key name: a search of {@link #keyNames} for each output made building a
     * monitor of n producing tasks take n squared string comparisons (10 000 tasks: a quarter
     * of a single-threaded run's CPU profile, before the first release).
     */
    private final Map<String, Integer> indexByName;

    /**
     * @param variables one per produced key, in the order the producers declared them
     * @param producers producing task by key name
     * @param consumers consuming tasks by key name
     */
    DataGraph(List<StateVariable<?>> variables, Map<String, String> producers, Map<String, List<String>> consumers) {
        this.variables = List.copyOf(variables);
        Map<String, StateVariable<?>> names = new LinkedHashMap<>();
        variables.forEach(v -> names.put(v.key().name(), v));
        this.byName = Map.copyOf(names);
        this.producers = Map.copyOf(producers);
        Map<String, List<String>> copied = new LinkedHashMap<>();
        consumers.forEach((k, v) -> copied.put(k, List.copyOf(v)));
        this.consumers = Map.copyOf(copied);
        this.keyNames = variables.stream().map(v -> v.key().name()).toList();
        Map<String, Integer> indices = new HashMap<>();
        for (int i = 0; i < keyNames.size(); i++) {
            indices.putIfAbsent(keyNames.get(i), i);
        }
        this.indexByName = Map.copyOf(indices);
    }

    /** @return the variables, by key index */
    List<StateVariable<?>> variables() {
        return variables;
    }

    /** @return key names by key index */
    List<String> keyNames() {
        return keyNames;
    }

    /** @return the key's index (see {@link MonitorListener#onCommit}), or -1 if no task produces it */
    int indexOf(String key) {
        return indexByName.getOrDefault(key, -1);
    }

    /**
     * @param key a key's name
     * @return its variable
     * @throws IllegalArgumentException naming the known keys if no task produces it
     */
    StateVariable<?> variable(String key) {
        StateVariable<?> variable = byName.get(key);
        if (variable == null) {
            throw new IllegalArgumentException("no key '" + key + "'; keys: " + keyNames);
        }
        return variable;
    }

    boolean hasKey(String key) {
        return byName.containsKey(key);
    }

    String producer(String key) {
        variable(key);
        return producers.get(key);
    }

    List<String> consumers(String key) {
        producer(key);
        return consumers.getOrDefault(key, List.of());
    }

    /** Copies a key's newest value into {@code target}, as a consumer's copy-in would; any thread. */
    <T extends StateValue<T>> long read(Key<T> key, T target) {
        StateVariable<?> variable = variable(key.name());
        if (!variable.key().type().equals(key.type())) {
            throw new IllegalArgumentException("key '" + key.name() + "' holds " + variable.key().type().getSimpleName()
                    + ", not " + key.type().getSimpleName());
        }
        @SuppressWarnings("unchecked")
        StateVariable<T> typed = (StateVariable<T>) variable;
        StateVariable.ReadCursor cursor = new StateVariable.ReadCursor();
        typed.copyTo(target, -1, cursor);
        return cursor.generation();
    }
}
