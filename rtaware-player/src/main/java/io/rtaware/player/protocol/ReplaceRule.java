package io.rtaware.player.protocol;

/**
 * Body of player REQ ADD_REPLACE_RULE ({@code player_add_replace_rule_req_t}); -1 in the
 * first four fields is a wildcard. Immutable and thread-safe.
 *
 * @param interf interface code or -1
 * @param index device index or -1
 * @param type message type or -1
 * @param subtype subtype or -1
 * @param replace {@link Subtypes#REPLACE_ACCEPT}, {@link Subtypes#REPLACE_REPLACE} or
 *     {@link Subtypes#REPLACE_IGNORE}
 */
public record ReplaceRule(int interf, int index, int type, int subtype, int replace) {

    /** @return the rule that keeps only the newest DATA message of every device and subtype */
    public static ReplaceRule latestDataOnly() {
        return new ReplaceRule(-1, -1, MessageType.DATA, -1, Subtypes.REPLACE_REPLACE);
    }
}
