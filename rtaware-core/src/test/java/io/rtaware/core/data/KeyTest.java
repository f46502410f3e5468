package io.rtaware.core.data;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertThrows;

import io.rtaware.core.Counter;
import io.rtaware.core.Scan;
import org.junit.jupiter.api.Test;

class KeyTest {

    @Test
    void acceptsLettersDigitsAndSeparators() {
        for (String name : new String[] {"laser", "motion.avoid", "robot0/pose", "a_b-c:d", "9lives"}) {
            assertEquals(name, Key.of(name, Counter.class, Counter::new).name(), "valid name " + name);
        }
    }

    @Test
    void rejectsBadNamesWithAMessageNamingThem() {
        for (String name : new String[] {"", ".laser", "has space", "laser!", "-x"}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                    () -> Key.of(name, Counter.class, Counter::new), name);
            assertEquals("key name '" + name + "' is not valid (letters, digits and _ . : / - only, not starting with punctuation)",
                    e.getMessage(), "message for '" + name + "'");
        }
    }

    @Test
    void keysAreEqualByNameAndType() {
        assertEquals(Counter.key("pose"), Counter.key("pose"), "same name and type");
        assertNotEquals(Counter.key("pose"), Scan.key("pose"), "same name, other type");
        assertEquals("pose:Counter", Counter.key("pose").toString(), "toString");
    }

    @Test
    void newBufferAllocatesAFreshInstanceAndChecksTheFactory() {
        Key<Counter> key = Counter.key("c");
        assertNotSame(key.newBuffer(), key.newBuffer(), "each buffer is new");
        Key<Counter> broken = Key.of("broken", Counter.class, () -> null);
        IllegalStateException e = assertThrows(IllegalStateException.class, broken::newBuffer);
        assertEquals("factory of key 'broken' returned null instead of " + Counter.class.getName(), e.getMessage(), "message");
    }

    @Test
    void stateVariableCopiesOnlyNewerGenerationsAndKeepsCommitTime() {
        StateVariable<Counter> variable = new StateVariable<>(Counter.key("c"));
        Counter source = new Counter();
        Counter target = new Counter();
        StateVariable.ReadCursor cursor = new StateVariable.ReadCursor();

        variable.copyTo(target, 0, cursor);
        assertEquals(0, cursor.generation(), "nothing committed yet");

        source.value = 7;
        variable.commit(source, 100);
        variable.copyTo(target, 0, cursor);
        assertEquals(7, target.value, "copied in");
        assertEquals(1, cursor.generation(), "generation 1");
        assertEquals(100, cursor.commitTimeNs(), "commit time");

        target.value = -1; // a consumer that scribbled on its buffer keeps its own copy while current
        variable.copyTo(target, 1, cursor);
        assertEquals(-1, target.value, "no copy when the held generation is current");
        assertEquals(100, cursor.commitTimeNs(), "commit time kept for an unchanged value");
    }
}
