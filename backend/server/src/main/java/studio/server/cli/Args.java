package studio.server.cli;

import java.io.PrintStream;
import java.util.function.Function;

/** Reading option values from a command line, for the studio's sub-commands. */
public final class Args {

    private Args() {
    }

    /** The value after an option, at {@code args[i]}. */
    public static String value(String[] args, int i, String option) {
        if (i >= args.length) {
            throw new IllegalArgumentException(option + " needs a value");
        }
        return args[i];
    }

    /** The value after an option as a number (validated later, with the scene, like any other value). */
    public static double number(String[] args, int i, String option) {
        String v = value(args, i, option);
        try {
            return Double.parseDouble(v);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(option + " needs a number, not '" + v + "'");
        }
    }

    /** The value after an option as a whole number of at least 1. */
    public static int positive(String[] args, int i, String option) {
        String v = value(args, i, option);
        try {
            int n = Integer.parseInt(v);
            if (n < 1) {
                throw new NumberFormatException();
            }
            return n;
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(option + " needs a positive whole number, not '" + v + "'");
        }
    }

    /**
     * A command's options read by {@code parse}, or null when the command line is not one of its
     * own ({@code parse} threw IllegalArgumentException): then the error and the usage are on
     * {@code err}, and the command ends with its exit code for bad arguments.
     */
    public static <T> T options(String[] args, Function<String[], T> parse, String usage, PrintStream err) {
        try {
            return parse.apply(args);
        } catch (IllegalArgumentException e) {
            err.println("error: " + e.getMessage());
            err.println(usage);
            return null;
        }
    }
}
