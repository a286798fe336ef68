package glint.study;

import java.util.Locale;

/** Number formatting for the generated tables and labels. */
final class Numbers {

    private Numbers() {
    }

    /** 1e-9, 2.5e-4, 0.1 as 1e-1, 0: a compact scientific form. */
    static String sci(double v) {
        if (v == 0) {
            return "0";
        }
        String[] parts = String.format(Locale.ROOT, "%.1e", v).split("e");
        String mantissa = parts[0].endsWith(".0") ? parts[0].substring(0, parts[0].length() - 2) : parts[0];
        return mantissa + "e" + Integer.parseInt(parts[1]);
    }

    /** A value with three significant digits, in scientific form. */
    static String sig3(double v) {
        return String.format(Locale.ROOT, "%.2e", v);
    }

    /** A percentage with one decimal: 12.5 %. */
    static String percent(double fraction) {
        return String.format(Locale.ROOT, "%.1f %%", 100 * fraction);
    }

    static String fixed(double v, int decimals) {
        return String.format(Locale.ROOT, "%." + decimals + "f", v);
    }
}
