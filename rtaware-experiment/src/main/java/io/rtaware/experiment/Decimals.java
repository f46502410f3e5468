package io.rtaware.experiment;

import java.math.BigDecimal;

/** How the experiment writes a decimal a user typed or will type: as written, without trailing zeros. */
public final class Decimals {

    private Decimals() {
    }

    /**
     * @param v a finite value, e.g. a top speed or a CPU quota
     * @return it in plain notation without trailing zeros: {@code 0.3}, {@code 1}, {@code 1.5}
     */
    public static String plain(double v) {
        return BigDecimal.valueOf(v).stripTrailingZeros().toPlainString();
    }
}
