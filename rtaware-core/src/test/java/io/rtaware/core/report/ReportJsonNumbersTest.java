package io.rtaware.core.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** report.json never holds "NaN" or "Infinity" (as a string or a bare token): a value the run did not give is null. */
class ReportJsonNumbersTest {

    record Section(double distanceM, Double travelledM, float ratio, double hugeM) {
    }

    private static Report emptyReport() {
        return new Report(Report.SCHEMA, 1.0, 1.0, Double.NaN, List.of(), List.of());
    }

    @Test
    void nonFiniteNumbersAreWrittenAsNull() throws Exception {
        ReportDocument doc = new ReportDocument(emptyReport())
                .section("run", new Section(Double.NaN, Double.POSITIVE_INFINITY, Float.NaN, 1e300));
        String json = doc.toJsonString();
        assertFalse(json.contains("NaN"), json);
        assertFalse(json.contains("Infinity"), json);
        JsonNode root = new ObjectMapper().readTree(json);
        assertTrue(root.get("misses_total_pct").isNull(), json);
        assertTrue(root.at("/run/distance_m").isNull(), json);
        assertTrue(root.at("/run/travelled_m").isNull(), json);
        assertTrue(root.at("/run/ratio").isNull(), json);
        assertEquals(1e300, root.at("/run/huge_m").asDouble(), "a huge value is written as it is");
    }

    @Test
    void jsonTreeSectionsAreCleanedToo() throws Exception {
        ObjectMapper mapper = ReportDocument.mapper();
        Map<String, Object> section = new LinkedHashMap<>();
        section.put("a", Double.NaN);
        section.put("list", List.of(1.0, Double.NEGATIVE_INFINITY));
        JsonNode tree = new ObjectMapper().createObjectNode().put("x", Double.NaN).put("y", 2.0);
        String json = new ReportDocument(emptyReport()).section("m", section).section("t", tree).toJsonString();
        assertFalse(json.contains("NaN") || json.contains("Infinity"), json);
        JsonNode root = mapper.readTree(json);
        assertTrue(root.at("/m/a").isNull(), json);
        assertTrue(root.at("/m/list/1").isNull(), json);
        assertTrue(root.at("/t/x").isNull(), json);
        assertEquals(2.0, root.at("/t/y").asDouble(), json);
    }

    @Test
    void everyMapperCopyWritesNull() throws Exception {
        String json = ReportDocument.mapper().writeValueAsString(Map.of("v", Double.NaN));
        assertFalse(json.contains("NaN"), json);
    }

    @Test
    void roundingNeverOverflows() {
        assertEquals(1.235, Rounding.toDecimals(1.2349, 3), "ordinary rounding");
        assertEquals(1e300, Rounding.toDecimals(1e300, 3), "a huge value stays itself, not Long.MAX_VALUE / 1000");
        assertEquals(-1e300, Rounding.toDecimals(-1e300, 2), "negative huge");
        assertEquals(9.007199254740993E15, Rounding.toDecimals(9.007199254740993E15, 3), "beyond 2^53 there is nothing to round");
        assertTrue(Double.isNaN(Rounding.toDecimals(Double.NaN, 3)), "NaN stays NaN (written as null)");
    }
}
