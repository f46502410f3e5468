package io.rtaware.app.live;

import io.rtaware.core.testing.Requirement;

/**
 * A headless Chromium for {@link Cdp} ({@code apt-get install -y chromium}). CI may lack it only
 * where {@code .ci/run} could not install it and said so with {@code RTAWARE_NO_CHROMIUM=1}.
 */
public final class HeadlessChromium implements Requirement {

    @Override
    public String name() {
        return "headless Chromium";
    }

    @Override
    public String missingReason() {
        return Cdp.chromium() == null
                ? "none at /usr/bin/chromium, chromium-browser or google-chrome (apt-get install -y chromium)" : null;
    }

    @Override
    public String excusedUnderCi() {
        return "1".equals(System.getenv("RTAWARE_NO_CHROMIUM")) ? "RTAWARE_NO_CHROMIUM=1: .ci/run could not install it"
                : null;
    }
}
