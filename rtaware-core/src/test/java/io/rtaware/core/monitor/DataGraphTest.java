package io.rtaware.core.monitor;

import static org.junit.jupiter.api.Assertions.assertEquals;

import io.rtaware.core.Counter;
import io.rtaware.core.data.Key;
import io.rtaware.core.data.StateVariable;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

class DataGraphTest {

    @Test
    void everyKeyHasTheIndexOfItsVariableAndAnUnknownKeyHasNone() {
        List<StateVariable<?>> variables = new ArrayList<>();
        for (int i = 0; i < 5; i++) {
            variables.add(new StateVariable<>(Key.of("k" + i, Counter.class, Counter::new)));
        }
        DataGraph graph = new DataGraph(variables, Map.of(), Map.of());

        for (int i = 0; i < 5; i++) {
            assertEquals(i, graph.indexOf("k" + i));
            assertEquals("k" + i, graph.keyNames().get(graph.indexOf("k" + i)));
        }
        assertEquals(-1, graph.indexOf("k5"));
    }
}
