package io.rtaware.record.encode;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.rtaware.robot.msg.LaserScan;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;

/** The JSON a recording carries reads back to the same value, bit for bit, and malformed JSON is named. */
class JsonStateCodecTest {

    @Test
    void aValueReadsBackBitForBitWithItsCountAndNonFiniteNumbers() {
        LaserScan scan = new LaserScan(8);
        scan.minAngleRad = -2.0943951023931953;
        scan.maxAngleRad = Double.NaN;
        scan.maxRangeM = Double.POSITIVE_INFINITY;
        scan.serverTimeS = 1e-7;
        scan.setCount(3);
        scan.rangesM[0] = 0.1f;
        scan.rangesM[1] = Float.NEGATIVE_INFINITY;
        scan.rangesM[2] = -0.0f;
        JsonStateCodec codec = new JsonStateCodec(LaserScan.class, false);
        ByteBuf json = new ByteBuf(64);
        codec.encode(scan, json);

        LaserScan back = new LaserScan(8);
        codec.decode(json.array(), 0, json.size(), back);
        assertEquals(3, back.count());
        assertEquals(Double.doubleToLongBits(scan.minAngleRad), Double.doubleToLongBits(back.minAngleRad));
        assertTrue(Double.isNaN(back.maxAngleRad));
        assertEquals(Double.POSITIVE_INFINITY, back.maxRangeM);
        assertEquals(1e-7, back.serverTimeS);
        assertEquals(0.1f, back.rangesM[0]);
        assertEquals(Float.NEGATIVE_INFINITY, back.rangesM[1]);
        assertEquals(Float.floatToIntBits(-0.0f), Float.floatToIntBits(back.rangesM[2]));
    }

    @Test
    void malformedOrIncompleteJsonIsNamedNotMisread() {
        JsonStateCodec codec = new JsonStateCodec(LaserScan.class, true);
        LaserScan into = new LaserScan(8);
        byte[] missing = "{\"minAngleRad\":1.0}".getBytes(StandardCharsets.US_ASCII);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> codec.decode(missing, 0, missing.length, into));
        assertTrue(e.getMessage().contains("lacks field maxAngleRad"), e.getMessage());
        byte[] broken = "{\"minAngleRad\":1.0,\"maxAngleRad\":tru".getBytes(StandardCharsets.US_ASCII);
        e = assertThrows(IllegalArgumentException.class, () -> codec.decode(broken, 0, broken.length, into));
        assertTrue(e.getMessage().contains("malformed"), e.getMessage());
        byte[] unknown = "{\"speed\":1}".getBytes(StandardCharsets.US_ASCII);
        e = assertThrows(IllegalArgumentException.class, () -> codec.decode(unknown, 0, unknown.length, into));
        assertTrue(e.getMessage().contains("unknown field \"speed\""), e.getMessage());
        LaserScan small = new LaserScan(1);
        JsonStateCodec full = new JsonStateCodec(LaserScan.class, false);
        byte[] tooMany = ("{\"minAngleRad\":0,\"maxAngleRad\":0,\"maxRangeM\":0,\"serverTimeS\":0,"
                + "\"rangesM\":[1.0,2.0],\"count\":2}").getBytes(StandardCharsets.US_ASCII);
        e = assertThrows(IllegalArgumentException.class, () -> full.decode(tooMany, 0, tooMany.length, small));
        assertTrue(e.getMessage().contains("exceeds the capacity"), e.getMessage());
    }
}
