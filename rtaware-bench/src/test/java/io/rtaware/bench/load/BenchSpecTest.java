package io.rtaware.bench.load;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;

/** {@code --stagger}: first releases spread over the period, exactly. */
class BenchSpecTest {

    private static final long MS = 1_000_000L;

    @Test
    void fourTasksOfOnePeriodAreReleasedAQuarterPeriodApart() {
        List<BenchSpec> specs = BenchSpec.staggered(List.of(BenchSpec.of("a", 10 * MS, 0), BenchSpec.of("b", 10 * MS, 0),
                BenchSpec.of("c", 10 * MS, 0), BenchSpec.of("d", 10 * MS, 0)));
        assertEquals(List.of(0L, 2_500_000L, 5_000_000L, 7_500_000L), specs.stream().map(BenchSpec::offsetNs).toList());
        assertEquals(7_500_000L, specs.get(3).schedule().offsetNs(), "the schedule carries the offset");
        assertEquals(10 * MS, specs.get(3).schedule().periodNs());
    }

    @Test
    void offsetsAreTheFloorOfIOverNOfEachTasksOwnPeriod() {
        List<BenchSpec> specs = BenchSpec.staggered(List.of(BenchSpec.of("a", 10, 0), BenchSpec.of("b", 10, 0),
                BenchSpec.of("c", 7 * MS, 0)));
        assertEquals(List.of(0L, 3L, 4_666_666L), specs.stream().map(BenchSpec::offsetNs).toList(),
                "10/3 -> 3 ns; 2 * 7 ms / 3 -> 4 666 666 ns (floor)");
    }

    @Test
    void tenThousandTasksOfAnHourStayExactWithoutOverflow() {
        long hourNs = 3_600_000_000_000L;
        List<BenchSpec> specs = new java.util.ArrayList<>();
        for (int i = 0; i < 10_000; i++) {
            specs.add(BenchSpec.of("t" + i, hourNs + 1, 0));
        }
        List<BenchSpec> staggered = BenchSpec.staggered(specs);
        for (int i = 0; i < 10_000; i += 997) {
            long expected = java.math.BigInteger.valueOf(i).multiply(java.math.BigInteger.valueOf(hourNs + 1))
                    .divide(java.math.BigInteger.valueOf(10_000)).longValueExact();
            assertEquals(expected, staggered.get(i).offsetNs(), "task " + i);
        }
    }

    @Test
    void withoutStaggerEveryTaskStartsAtTheStart() {
        assertEquals(0, BenchSpec.of("a", 10 * MS, 0).offsetNs());
        assertEquals(0, BenchSpec.parseList("a:10ms:1ms,b:20ms..40ms:1ms").get(1).schedule().offsetNs());
    }
}
