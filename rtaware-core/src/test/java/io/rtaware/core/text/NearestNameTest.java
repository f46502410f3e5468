package io.rtaware.core.text;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

class NearestNameTest {

    private static final List<String> SCENARIOS = List.of("paper-room", "corridor", "office");

    @Test
    void aTypoGetsTheNameItWasMeantToBe() {
        assertEquals(Optional.of("office"), NearestName.of("ofice", SCENARIOS), "a letter left out");
        assertEquals(Optional.of("office"), NearestName.of("offcie", SCENARIOS), "two letters swapped");
        assertEquals(Optional.of("corridor"), NearestName.of("Coridor", SCENARIOS), "case is ignored");
        assertEquals(Optional.of("paper-room"), NearestName.of("paper_room", SCENARIOS), "one letter changed");
        assertEquals(Optional.of("paper-room"), NearestName.of("paperroom", SCENARIOS), "a letter left out");
    }

    @Test
    void nothingCloseIsNoSuggestion() {
        assertEquals(Optional.empty(), NearestName.of("warehouse", SCENARIOS));
        assertEquals(Optional.empty(), NearestName.of("x", List.of("ab")), "two edits for a short name is too far");
        assertEquals(Optional.empty(), NearestName.of("office", SCENARIOS), "the name itself is not a typo");
        assertEquals(Optional.empty(), NearestName.of("office", List.of()), "nothing known");
    }

    @Test
    void theSuggestionReadsAsTheEndOfAMessage() {
        assertEquals("; did you mean 'corridor'?", NearestName.suggestion("corrdior", SCENARIOS));
        assertEquals("", NearestName.suggestion("warehouse", SCENARIOS));
    }

    @Test
    void distanceCountsEachEditOnce() {
        assertEquals(0, NearestName.distance("bench", "bench"));
        assertEquals(1, NearestName.distance("bnech", "bench"), "a swap is one edit");
        assertEquals(3, NearestName.distance("", "abc"));
        assertEquals(2, NearestName.distance("kitten", "sittin"));
    }
}
