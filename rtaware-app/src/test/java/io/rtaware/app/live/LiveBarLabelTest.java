package io.rtaware.app.live;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import io.rtaware.core.testing.Waits;
import io.rtaware.live.LiveView;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Objects;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The live page's exec-p99-of-period bar, as a browser lays it out: its figure ({@code 273%} for
 * a task over its period, whose fill is red) is not drawn on the fill, and reads dark on light
 * with a WCAG contrast of at least 4.5. Skipped, saying so, without Chromium.
 */
class LiveBarLabelTest {

    private static final Pattern RGB = Pattern.compile("rgba?\\((\\d+), (\\d+), (\\d+)(, ([\\d.]+))?\\)");

    @TempDir
    Path dir;

    @Test
    void theBarsFigureIsReadableBesideItsFill() throws Exception {
        Path chromium = Cdp.chromium();
        Assumptions.assumeTrue(chromium != null,
                "SKIPPED: headless Chromium not found (/usr/bin/chromium); install it with apt-get install -y chromium");
        Path page = dir.resolve("live.html");
        try (InputStream in = Objects.requireNonNull(LiveView.class.getResourceAsStream("live.html"))) {
            Files.copy(in, page);
        }
        try (Cdp browser = Cdp.launch(chromium, dir.resolve("profile"))) {
            browser.navigate(page.toUri().toString());
            // Page.navigate answers before the page's script has run: a layout asked for sooner
            // finds no taskRows and returns no colours (seen once in CI).
            Waits.until(() -> browser.eval("typeof taskRows === 'function' && document.readyState === 'complete'")
                    .asBoolean(), Duration.ofSeconds(30), "the live page's script, loaded");
            for (double ratio : new double[] {2.73, 0.8, 0.3}) {
                JsonNode r = browser.eval(LAYOUT.replace("RATIO", Double.toString(ratio)));
                assertFalse(r.path("overlap").asBoolean(), "the figure is not drawn on the bar's fill: " + r);
                double contrast = contrast(r.path("fg").asText(), r.path("bg").asText());
                assertTrue(contrast >= 4.5, "the figure " + r.path("text").asText() + " reads with contrast "
                        + contrast + ": " + r);
            }
        }
    }

    /** Lays out one task row with the page's own code and reports where the figure and the fill are. */
    private static final String LAYOUT = "(() => { const t = document.createElement('table');"
            + " t.innerHTML = '<tbody>' + taskRows({ tasks: [{ name: 'planner', period_ms: 100, runs: 10, misses: 1,"
            + " miss_pct: 10, recent_miss_pct: 10, stale_runs: 0, recent_exec_p99_ms: 100 * RATIO,"
            + " recent_exec_p99_of_period: RATIO }] }) + '</tbody>'; document.body.appendChild(t);"
            + " const fill = t.querySelector('.bar i'); const label = [...t.querySelectorAll('td')].pop()"
            + ".querySelector('em');"
            + " const a = label.getBoundingClientRect(), b = fill.getBoundingClientRect();"
            + " const overlap = a.left < b.right && b.left < a.right && a.top < b.bottom && b.top < a.bottom;"
            + " let el = label, bg = 'rgba(0, 0, 0, 0)';"
            + " while (el && (bg = getComputedStyle(el).backgroundColor) === 'rgba(0, 0, 0, 0)') el = el.parentElement;"
            + " const r = { overlap: overlap, fg: getComputedStyle(label).color, bg: el ? bg : 'rgb(255, 255, 255)',"
            + " text: label.textContent }; t.remove(); return r; })()";

    private static double contrast(String a, String b) {
        double la = luminance(a);
        double lb = luminance(b);
        return (Math.max(la, lb) + 0.05) / (Math.min(la, lb) + 0.05);
    }

    private static double luminance(String css) {
        Matcher m = RGB.matcher(css);
        assertTrue(m.matches(), "a computed colour: " + css);
        assertTrue(m.group(5) == null || Double.parseDouble(m.group(5)) == 1.0, "an opaque colour: " + css);
        double[] c = new double[3];
        for (int i = 0; i < 3; i++) {
            double v = Integer.parseInt(m.group(i + 1)) / 255.0;
            c[i] = v <= 0.04045 ? v / 12.92 : Math.pow((v + 0.055) / 1.055, 2.4);
        }
        return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
    }
}
