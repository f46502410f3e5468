package io.rtaware.sim.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.player.protocol.Interfaces;
import io.rtaware.player.protocol.MessageType;
import io.rtaware.player.protocol.ReplaceRule;
import io.rtaware.player.protocol.Subtypes;
import org.junit.jupiter.api.Test;

class ReplaceRulesTest {

    private static final Outgoing LASER_SCAN = new Outgoing(new byte[0], Interfaces.LASER, 0, MessageType.DATA,
            Subtypes.LASER_DATA_SCAN);
    private static final Outgoing ODOMETRY = new Outgoing(new byte[0], Interfaces.POSITION2D, 0, MessageType.DATA,
            Subtypes.POSITION2D_DATA_STATE);

    @Test
    void theNewestMatchingRuleDecidesAndANewRuleChangesACachedDecision() {
        ReplaceRules rules = new ReplaceRules(4);
        assertEquals(Subtypes.REPLACE_ACCEPT, rules.decide(LASER_SCAN), "no rule: accept");
        assertTrue(rules.add(ReplaceRule.latestDataOnly()));
        assertEquals(Subtypes.REPLACE_REPLACE, rules.decide(LASER_SCAN));
        assertTrue(rules.add(new ReplaceRule(Interfaces.LASER, -1, -1, -1, Subtypes.REPLACE_IGNORE)));
        assertEquals(Subtypes.REPLACE_IGNORE, rules.decide(LASER_SCAN), "the newer rule decides");
        assertEquals(Subtypes.REPLACE_REPLACE, rules.decide(ODOMETRY), "the laser rule does not match odometry");
    }

    @Test
    void distinctRulesAreCappedAndAnEqualRuleReplacesItsElder() {
        ReplaceRules rules = new ReplaceRules(2);
        assertTrue(rules.add(new ReplaceRule(Interfaces.LASER, 0, -1, -1, Subtypes.REPLACE_IGNORE)));
        assertTrue(rules.add(ReplaceRule.latestDataOnly()));
        assertFalse(rules.add(new ReplaceRule(Interfaces.RANGER, 0, -1, -1, Subtypes.REPLACE_IGNORE)), "a third");
        assertEquals(Subtypes.REPLACE_REPLACE, rules.decide(LASER_SCAN));
        assertTrue(rules.add(new ReplaceRule(Interfaces.LASER, 0, -7, -1, Subtypes.REPLACE_ACCEPT)),
                "same criteria (any negative is a wildcard): replaces, and is the newest");
        assertEquals(2, rules.size());
        assertEquals(Subtypes.REPLACE_ACCEPT, rules.decide(LASER_SCAN));
    }
}
