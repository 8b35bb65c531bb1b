package studio.server.cli;

import java.io.Console;
import java.io.PrintStream;
import java.lang.reflect.Method;
import java.util.Locale;

import studio.engine.render.Film;
import studio.engine.render.TileRect;

/** A one-line progress bar redrawn in place on a terminal: [#####-----]  48%  tiles 230/480  1.2 s. */
final class ProgressBar {

    private static final int WIDTH = 30;

    private final PrintStream out;
    private final long start = System.nanoTime();
    private int lastPercent = -1;

    private ProgressBar(PrintStream out) {
        this.out = out;
    }

    /** A bar on {@code out} if the process runs on a terminal, else null (logs and pipes stay clean). */
    static ProgressBar forTerminal(PrintStream out) {
        return isTerminal() ? new ProgressBar(out) : null;
    }

    private static boolean isTerminal() {
        Console console = System.console();
        if (console == null) {
            return false;
        }
        try { // Java 22+: a console exists even when redirected; ask whether it is a terminal
            Method isTerminal = Console.class.getMethod("isTerminal");
            return (Boolean) isTerminal.invoke(console);
        } catch (ReflectiveOperationException e) {
            return true;
        }
    }

    synchronized void tileFinished(Film film, TileRect tile, int done, int total) {
        int percent = (int) (100L * done / total);
        if (percent == lastPercent) {
            return;
        }
        lastPercent = percent;
        int filled = WIDTH * done / total;
        out.printf(Locale.ROOT, "\r[%s%s] %3d%%  tiles %d/%d  %.1f s", "#".repeat(filled), "-".repeat(WIDTH - filled),
                percent, done, total, (System.nanoTime() - start) / 1e9);
        out.flush();
    }

    synchronized void finish() {
        out.print("\r" + " ".repeat(WIDTH + 40) + "\r");
        out.flush();
    }
}
