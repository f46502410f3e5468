package io.rtaware.sim.server;

import io.rtaware.player.protocol.ReplaceRule;
import io.rtaware.player.protocol.Subtypes;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * One client's replace rules: the newest rule matching a message decides (a negative field is a
 * wildcard); without a match a message is accepted. A rule with the same four fields as an older
 * one replaces it (as Player does), so only distinct rules count against the limit; beyond the
 * limit {@link #add} refuses. The decision per message kind is cached until the rules change,
 * so a data message costs one lookup, not a scan. Not thread-safe (the client's queue guards it).
 */
final class ReplaceRules {

    private final int maxRules;
    /** Oldest first; fields normalised (every wildcard is -1). */
    private final List<ReplaceRule> rules = new ArrayList<>();
    private final Map<Long, Integer> decisions = new HashMap<>();

    /** @param maxRules most distinct rules, positive */
    ReplaceRules(int maxRules) {
        if (maxRules < 1) {
            throw new IllegalArgumentException("maxRules must be positive, got " + maxRules);
        }
        this.maxRules = maxRules;
    }

    /**
     * @param rule the rule (its replace value already validated)
     * @return false if the client already has {@code maxRules} rules and this one replaces none
     */
    boolean add(ReplaceRule rule) {
        ReplaceRule r = new ReplaceRule(wild(rule.interf()), wild(rule.index()), wild(rule.type()),
                wild(rule.subtype()), rule.replace());
        int same = -1;
        for (int i = 0; i < rules.size(); i++) {
            ReplaceRule old = rules.get(i);
            if (old.interf() == r.interf() && old.index() == r.index() && old.type() == r.type()
                    && old.subtype() == r.subtype()) {
                same = i;
                break;
            }
        }
        if (same >= 0) {
            rules.remove(same);
        } else if (rules.size() >= maxRules) {
            return false;
        }
        rules.add(r);
        decisions.clear();
        return true;
    }

    /** @return the distinct rules held */
    int size() {
        return rules.size();
    }

    /**
     * @param m an outgoing message
     * @return {@link Subtypes#REPLACE_ACCEPT}, {@link Subtypes#REPLACE_REPLACE} or
     *     {@link Subtypes#REPLACE_IGNORE} for it
     */
    int decide(Outgoing m) {
        long kind = (m.interf() & 0xffffL) << 48 | (m.index() & 0xffffL) << 32 | (m.type() & 0xffffL) << 16
                | (m.subtype() & 0xffffL);
        Integer known = decisions.get(kind);
        if (known != null) {
            return known;
        }
        int replace = Subtypes.REPLACE_ACCEPT;
        for (int i = rules.size() - 1; i >= 0; i--) {
            ReplaceRule r = rules.get(i);
            if ((r.interf() < 0 || r.interf() == m.interf()) && (r.index() < 0 || r.index() == m.index())
                    && (r.type() < 0 || r.type() == m.type()) && (r.subtype() < 0 || r.subtype() == m.subtype())) {
                replace = r.replace();
                break;
            }
        }
        decisions.put(kind, replace);
        return replace;
    }

    private static int wild(int field) {
        return field < 0 ? -1 : field;
    }
}
