package io.rtaware.ros2.task;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.zenoh.ZenohException;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** When the data task asks the ROS graph about a silent input topic, and what it says, on exact world times. */
class PublishedTypeWatchTest {

    private static final long S = 1_000_000_000L;
    private static final String LASER_SCAN = "sensor_msgs/msg/LaserScan";

    /** The graph as the test sets it; counts the questions, by world time. */
    private final Set<String> published = new LinkedHashSet<>();
    private final List<Long> askedAt = new ArrayList<>();
    private final List<String> lines = new ArrayList<>();
    private long nowNs;
    private final PublishedTypeWatch watch = new PublishedTypeWatch("/scan", "rt/scan", LASER_SCAN, S, topic -> {
        assertEquals("/scan", topic, "the watch asks about its topic");
        askedAt.add(nowNs);
        return Set.copyOf(published);
    }, lines::add);

    private void checkAt(long atNs) {
        nowNs = atNs;
        watch.check(atNs);
    }

    @Test
    void aTopicPublishedAsAnotherTypeIsToldOnceAtTheFirstQuestion() {
        published.add("geometry_msgs/msg/Twist");
        checkAt(5 * S);                // the first cycle: the interval starts
        checkAt(5 * S + S - 1);        // not yet
        assertEquals(List.of(), askedAt, "no question within the first interval");
        checkAt(6 * S);
        assertEquals(List.of(6 * S), askedAt, "asked one interval after the first check");
        assertEquals(List.of("rt/scan is published as geometry_msgs/msg/Twist, rtaware expects "
                + "sensor_msgs/msg/LaserScan: none of its samples can be read"), lines);
        assertTrue(watch.ended());
        checkAt(20 * S);
        assertEquals(1, askedAt.size(), "never asked again");
        assertEquals(1, lines.size(), "told once");
    }

    @Test
    void aTopicNobodyPublishesIsAskedAboutEveryIntervalUntilItsFirstUsableSample() {
        checkAt(0);
        checkAt(S);
        checkAt(S + S / 2);
        checkAt(2 * S + S / 2);
        checkAt(3 * S);
        assertEquals(List.of(S, 2 * S + S / 2), askedAt, "one question per interval, counted from the last one");
        watch.usable();
        published.add("geometry_msgs/msg/Twist");
        checkAt(10 * S);
        assertEquals(2, askedAt.size(), "a usable sample ends the watch");
        assertEquals(List.of(), lines, "nothing to tell");
    }

    @Test
    void aPublisherOfTheExpectedTypeBesideAnotherExplainsNothingAndEndsTheWatch() {
        published.add("geometry_msgs/msg/Twist");
        published.add(LASER_SCAN);
        checkAt(0);
        checkAt(S);
        assertEquals(List.of(), lines, "the silence has another cause");
        assertTrue(watch.ended(), "a publisher of the right type: no more questions");
        published.remove(LASER_SCAN);
        checkAt(2 * S);
        assertEquals(List.of(S), askedAt, "asked once");
    }

    @Test
    void aSampleThatDoesNotDecodeBringsTheFirstQuestionForwardButNoOther() {
        checkAt(0);
        watch.undecodable();
        checkAt(S / 10);
        assertEquals(List.of(S / 10), askedAt, "asked at the next check after an undecodable sample");
        watch.undecodable();
        checkAt(S / 5);
        assertEquals(List.of(S / 10), askedAt, "only the first question comes early");
        published.add("geometry_msgs/msg/Twist");
        checkAt(S / 10 + S);
        assertEquals(List.of(S / 10, S / 10 + S), askedAt, "then every interval");
        assertEquals(1, lines.size(), lines.toString());
    }

    @Test
    void severalOtherTypesAreNamedTogether() {
        published.add("geometry_msgs/msg/Twist");
        published.add("Foo");
        checkAt(0);
        checkAt(S);
        assertTrue(lines.get(0).startsWith("rt/scan is published as "), lines.toString());
        assertTrue(lines.get(0).contains("geometry_msgs/msg/Twist") && lines.get(0).contains(" and ")
                && lines.get(0).contains("Foo"), lines.toString());
    }

    @Test
    void aGraphThatCannotBeAskedIsToldOnceAndEndsTheWatch() {
        PublishedTypeWatch broken = new PublishedTypeWatch("/odom", "/odom", "nav_msgs/msg/Odometry", S, topic -> {
            throw new ZenohException("the Zenoh session is closed");
        }, lines::add);
        broken.check(0);
        broken.check(S);
        broken.check(2 * S);
        assertEquals(List.of("the ROS graph could not be asked which types /odom is published as: "
                + "the Zenoh session is closed"), lines);
        assertTrue(broken.ended());
    }

    @Test
    void theIntervalMustBePositive() {
        assertThrows(IllegalArgumentException.class, () -> new PublishedTypeWatch("/scan", "rt/scan", LASER_SCAN, 0,
                topic -> Set.of(), lines::add));
    }
}
