package io.rtaware.player;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.List;

/** Loads the recorded Player sessions from the test resources. */
public final class Captures {

    /** The two recorded sessions. */
    public static final List<String> SESSIONS = List.of("pull", "push-with-ranger");

    private Captures() {
    }

    /**
     * @param session folder name
     * @param file file name
     * @return the file's bytes
     */
    public static byte[] bytes(String session, String file) {
        try (InputStream in = Captures.class.getResourceAsStream("/captures/" + session + "/" + file)) {
            if (in == null) {
                throw new IllegalStateException("missing capture " + session + "/" + file);
            }
            return in.readAllBytes();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * @param session folder name
     * @return every entry of the session's index.json
     */
    public static List<JsonNode> index(String session) {
        try {
            JsonNode root = new ObjectMapper().readTree(bytes(session, "index.json"));
            List<JsonNode> out = new ArrayList<>();
            root.get("messages").forEach(out::add);
            return out;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * @param session folder name
     * @param dir {@code c2s} or {@code s2c}
     * @return the MESSAGE entries of that direction, in stream order
     */
    public static List<JsonNode> messages(String session, String dir) {
        List<JsonNode> out = new ArrayList<>();
        for (JsonNode m : index(session)) {
            if (m.get("dir").asText().equals(dir) && m.get("kind").asText().equals("MESSAGE")) {
                out.add(m);
            }
        }
        out.sort((a, b) -> Long.compare(a.get("offset").asLong(), b.get("offset").asLong()));
        return out;
    }
}
