package io.rtaware.sim.map;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.dataformat.yaml.YAMLFactory;
import java.awt.image.BufferedImage;
import java.awt.image.Raster;
import java.io.BufferedInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.Iterator;
import java.util.Locale;
import javax.imageio.ImageIO;
import javax.imageio.ImageReader;
import javax.imageio.stream.ImageInputStream;

/**
 * Loads ROS {@code map_server} maps: a YAML file with {@code image} (PGM P5/P2 or PNG, relative
 * to the YAML file), {@code resolution}, {@code origin: [x, y, yaw]}, {@code occupied_thresh},
 * {@code free_thresh} and {@code negate}. As in map_server, a pixel's occupancy probability is
 * {@code (255 - v) / 255} ({@code v / 255} with {@code negate: 1}); above
 * {@code occupied_thresh} the cell is occupied, below {@code free_thresh} free, otherwise
 * unknown. Image row 0 is the top of the map (largest y). Only {@code origin} yaw 0 is
 * supported. Colour images use the mean of their colour channels.
 *
 * <p>Limits, checked before anything large is allocated: the image's width x height (read
 * from its header, before any pixel is decoded) must be at most {@link #maxPixels()}, half of
 * the JVM's maximum heap at {@value #PEAK_BYTES_PER_PIXEL} bytes per pixel (what loading and
 * the simulator's distance field take at their peak); {@code resolution} must be from
 * {@value #MIN_RESOLUTION_M} to {@value #MAX_RESOLUTION_M} metres per pixel.
 *
 * <p>Every failure is a {@link MapException} with a one-line message naming the file, the field
 * and the value. Stateless and thread-safe.
 */
public final class MapLoader {

    /** Opens files named relative to the map YAML (a directory or a classpath folder). */
    @FunctionalInterface
    public interface Opener {
        /**
         * @param relativeName the name as written in the YAML
         * @return an open stream; the caller closes it
         * @throws IOException if it cannot be opened
         */
        InputStream open(String relativeName) throws IOException;
    }

    /**
     * Heap bytes per map pixel at the peak of loading: the decoded pixel values (4), the cell
     * states (up to 8), the image itself (up to 8 for 16-bit RGBA), and the map's cells (1),
     * distance field (4) and its squared-distance pass (8), plus slack for the pass's row buffers.
     */
    public static final int PEAK_BYTES_PER_PIXEL = 40;
    /** Finest resolution accepted, metres per pixel. */
    public static final double MIN_RESOLUTION_M = 0.001;
    /** Coarsest resolution accepted, metres per pixel. */
    public static final double MAX_RESOLUTION_M = 100;

    private static final ObjectMapper YAML = new ObjectMapper(new YAMLFactory());

    private MapLoader() {
    }

    /**
     * @return the most pixels a map image may have in this JVM: half the maximum heap
     *     ({@code -Xmx}) divided by {@value #PEAK_BYTES_PER_PIXEL} bytes per pixel
     */
    public static long maxPixels() {
        return Runtime.getRuntime().maxMemory() / 2 / PEAK_BYTES_PER_PIXEL;
    }

    /**
     * @param yamlFile the map YAML file
     * @return the loaded map
     * @throws MapException if the file or its image is missing, malformed or too large for the heap
     */
    public static OccupancyMap load(Path yamlFile) {
        return load(yamlFile, maxPixels());
    }

    /**
     * @param yamlFile the map YAML file
     * @param maxPixels the most pixels the image may have
     * @return the loaded map
     * @throws MapException if the file or its image is missing, malformed or too large
     */
    public static OccupancyMap load(Path yamlFile, long maxPixels) {
        Path dir = yamlFile.toAbsolutePath().getParent();
        try (InputStream in = Files.newInputStream(yamlFile)) {
            return load(yamlFile.toString(), in, name -> Files.newInputStream(dir.resolve(name)), maxPixels);
        } catch (NoSuchFileException e) {
            throw new MapException(yamlFile + ": file not found");
        } catch (IOException e) {
            throw new MapException(yamlFile + ": cannot read: " + e.getMessage(), e);
        }
    }

    /**
     * @param sourceName the name of the YAML used in messages
     * @param yaml the YAML content
     * @param opener opens the image named in the YAML
     * @return the loaded map
     * @throws MapException if the YAML or its image is malformed or too large for the heap
     */
    public static OccupancyMap load(String sourceName, InputStream yaml, Opener opener) {
        return load(sourceName, yaml, opener, maxPixels());
    }

    /**
     * @param sourceName the name of the YAML used in messages
     * @param yaml the YAML content
     * @param opener opens the image named in the YAML
     * @param maxPixels the most pixels the image may have
     * @return the loaded map
     * @throws MapException if the YAML or its image is malformed or too large
     */
    public static OccupancyMap load(String sourceName, InputStream yaml, Opener opener, long maxPixels) {
        JsonNode root;
        try {
            root = YAML.readTree(yaml);
        } catch (IOException e) {
            throw new MapException(sourceName + ": not valid YAML: " + oneLine(e.getMessage()), e);
        }
        if (root == null || !root.isObject()) {
            throw new MapException(sourceName + ": expected a YAML mapping, got " + root);
        }
        JsonNode imageNode = required(sourceName, root, "image");
        if (!imageNode.isTextual() || imageNode.asText().isBlank()) {
            throw new MapException(sourceName + ": field 'image' must be a file name, got " + imageNode);
        }
        String image = imageNode.asText();
        double resolution = number(sourceName, root, "resolution");
        if (!(resolution >= MIN_RESOLUTION_M && resolution <= MAX_RESOLUTION_M)) {
            throw new MapException(sourceName + ": field 'resolution' must be from " + MIN_RESOLUTION_M + " to "
                    + (long) MAX_RESOLUTION_M + " metres per pixel, got " + resolution);
        }
        JsonNode origin = required(sourceName, root, "origin");
        if (!origin.isArray() || origin.size() != 3 || !origin.get(0).isNumber()
                || !origin.get(1).isNumber() || !origin.get(2).isNumber()) {
            throw new MapException(sourceName + ": field 'origin' must be [x, y, yaw] numbers, got " + origin);
        }
        if (origin.get(2).asDouble() != 0.0) {
            throw new MapException(sourceName + ": field 'origin' yaw must be 0 (rotated maps are not supported), got "
                    + origin.get(2).asDouble());
        }
        double occupiedThresh = number(sourceName, root, "occupied_thresh");
        double freeThresh = number(sourceName, root, "free_thresh");
        if (!(occupiedThresh >= 0 && occupiedThresh <= 1)) {
            throw new MapException(sourceName + ": field 'occupied_thresh' must be in [0, 1], got " + occupiedThresh);
        }
        if (!(freeThresh >= 0 && freeThresh <= occupiedThresh)) {
            throw new MapException(sourceName + ": field 'free_thresh' must be in [0, occupied_thresh], got "
                    + freeThresh);
        }
        JsonNode negateNode = required(sourceName, root, "negate");
        boolean negate;
        if (negateNode.isBoolean()) {
            negate = negateNode.asBoolean();
        } else if (negateNode.isInt() && (negateNode.asInt() == 0 || negateNode.asInt() == 1)) {
            negate = negateNode.asInt() == 1;
        } else {
            throw new MapException(sourceName + ": field 'negate' must be 0 or 1, got " + negateNode);
        }
        GrayImage gray;
        String imageName = sourceName + " -> " + image;
        try (InputStream in = new BufferedInputStream(opener.open(image))) {
            gray = readImage(imageName, image, in, maxPixels);
        } catch (InvalidPathException e) {
            throw new MapException(sourceName + ": field 'image' is not a file name this system can use ("
                    + e.getReason() + "; with LC_ALL=C only ASCII names work), got " + image);
        } catch (NoSuchFileException e) {
            throw new MapException(sourceName + ": field 'image' names a missing file, got " + image);
        } catch (IOException e) {
            throw new MapException(sourceName + ": field 'image' cannot be read (" + image + "): "
                    + oneLine(e.getMessage()), e);
        }
        OccupancyMap.CellState[] states = new OccupancyMap.CellState[gray.width * gray.height];
        for (int imgRow = 0; imgRow < gray.height; imgRow++) {
            int row = gray.height - 1 - imgRow;
            for (int col = 0; col < gray.width; col++) {
                double v = gray.values[imgRow * gray.width + col] / (double) gray.maxValue;
                double p = negate ? v : 1.0 - v;
                OccupancyMap.CellState s;
                if (p > occupiedThresh) {
                    s = OccupancyMap.CellState.OCCUPIED;
                } else if (p < freeThresh) {
                    s = OccupancyMap.CellState.FREE;
                } else {
                    s = OccupancyMap.CellState.UNKNOWN;
                }
                states[row * gray.width + col] = s;
            }
        }
        return new OccupancyMap(sourceName, gray.width, gray.height, resolution,
                origin.get(0).asDouble(), origin.get(1).asDouble(), states);
    }

    private record GrayImage(int width, int height, int maxValue, int[] values) {
    }

    private static GrayImage readImage(String name, String image, InputStream in, long maxPixels) throws IOException {
        String lower = image.toLowerCase(Locale.ROOT);
        if (lower.endsWith(".pgm")) {
            return readPgm(name, in, maxPixels);
        }
        BufferedImage img;
        try (ImageInputStream stream = ImageIO.createImageInputStream(in)) {
            Iterator<ImageReader> readers = stream == null ? null : ImageIO.getImageReaders(stream);
            if (readers == null || !readers.hasNext()) {
                throw new MapException(name + ": field 'image' is not a PGM or a readable PNG, got " + image);
            }
            ImageReader reader = readers.next();
            try {
                reader.setInput(stream, true, true);
                checkSize(name, reader.getWidth(0), reader.getHeight(0), maxPixels);
                img = reader.read(0);
            } finally {
                reader.dispose();
            }
        }
        Raster raster = img.getRaster();
        int bands = raster.getNumBands();
        boolean alpha = img.getColorModel().hasAlpha();
        int colourBands = alpha ? bands - 1 : bands;
        int bits = img.getColorModel().getComponentSize(0);
        int max = (1 << bits) - 1;
        int w = img.getWidth();
        int h = img.getHeight();
        int[] values = new int[w * h];
        int[] px = new int[bands];
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                raster.getPixel(x, y, px);
                long sum = 0;
                for (int b = 0; b < colourBands; b++) {
                    sum += px[b];
                }
                values[y * w + x] = (int) (sum / colourBands);
            }
        }
        return new GrayImage(w, h, max, values);
    }

    private static void checkSize(String name, int width, int height, long maxPixels) {
        long pixels = (long) width * height;
        if (pixels > maxPixels) {
            throw new MapException(String.format(Locale.ROOT, "%s: the image is %d x %d pixels (%d); this JVM's heap "
                    + "allows maps of at most %d pixels (%d bytes per pixel while loading, half the heap): use a smaller "
                    + "image, or raise the heap (RTAWARE_JAVA_OPTS=\"-Xmx4g ...\", see docs/troubleshooting.md)",
                    name, width, height, pixels, maxPixels, PEAK_BYTES_PER_PIXEL));
        }
    }

    private static GrayImage readPgm(String name, InputStream in, long maxPixels) throws IOException {
        String magic = token(name, in);
        boolean binary;
        if ("P5".equals(magic)) {
            binary = true;
        } else if ("P2".equals(magic)) {
            binary = false;
        } else {
            throw new MapException(name + ": PGM magic must be P5 or P2, got " + magic);
        }
        int w = positiveInt(name, "width", token(name, in));
        int h = positiveInt(name, "height", token(name, in));
        int max = positiveInt(name, "maxval", token(name, in));
        if (max > 65535) {
            throw new MapException(name + ": PGM maxval must be at most 65535, got " + max);
        }
        checkSize(name, w, h, Math.min(maxPixels, Integer.MAX_VALUE / 2));
        int[] values = new int[w * h];
        if (binary) {
            int bytesPer = max < 256 ? 1 : 2;
            byte[] data = in.readNBytes(w * h * bytesPer);
            if (data.length != w * h * bytesPer) {
                throw new MapException(name + ": PGM pixel data truncated, got " + data.length + " of "
                        + (w * h * bytesPer) + " bytes");
            }
            for (int i = 0; i < values.length; i++) {
                values[i] = bytesPer == 1 ? data[i] & 0xff
                        : ((data[2 * i] & 0xff) << 8) | (data[2 * i + 1] & 0xff);
            }
        } else {
            for (int i = 0; i < values.length; i++) {
                String t = token(name, in);
                if (t.isEmpty()) {
                    throw new MapException(name + ": PGM pixel data truncated, got " + i + " of "
                            + values.length + " values");
                }
                values[i] = intValue(name, "pixel", t);
            }
        }
        for (int i = 0; i < values.length; i++) {
            if (values[i] > max) {
                throw new MapException(name + ": PGM pixel above maxval " + max + ", got " + values[i]);
            }
        }
        return new GrayImage(w, h, max, values);
    }

    /** Reads one whitespace-separated token, skipping '#' comments; consumes one trailing whitespace. */
    private static String token(String name, InputStream in) throws IOException {
        StringBuilder sb = new StringBuilder();
        int c = in.read();
        while (c != -1) {
            if (c == '#') {
                while (c != -1 && c != '\n' && c != '\r') {
                    c = in.read();
                }
            } else if (Character.isWhitespace(c)) {
                c = in.read();
            } else {
                break;
            }
        }
        while (c != -1 && !Character.isWhitespace(c)) {
            sb.append((char) c);
            if (sb.length() > 32) {
                throw new MapException(name + ": PGM header token too long, got " + sb);
            }
            c = in.read();
        }
        return sb.toString();
    }

    private static int intValue(String name, String field, String t) {
        try {
            return Integer.parseInt(t);
        } catch (NumberFormatException e) {
            throw new MapException(name + ": PGM " + field + " must be an integer, got '" + t + "'");
        }
    }

    private static int positiveInt(String name, String field, String t) {
        int v = intValue(name, field, t);
        if (v <= 0) {
            throw new MapException(name + ": PGM " + field + " must be positive, got " + v);
        }
        return v;
    }

    private static JsonNode required(String source, JsonNode root, String field) {
        JsonNode n = root.get(field);
        if (n == null || n.isNull()) {
            throw new MapException(source + ": field '" + field + "' is missing");
        }
        return n;
    }

    private static double number(String source, JsonNode root, String field) {
        JsonNode n = required(source, root, field);
        if (!n.isNumber()) {
            throw new MapException(source + ": field '" + field + "' must be a number, got " + n);
        }
        return n.asDouble();
    }

    static String oneLine(String s) {
        return s == null ? "" : s.replaceAll("\\s*\\R\\s*", " ").trim();
    }
}
