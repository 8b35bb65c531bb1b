package studio.bench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/** Runs one renderer as a process and times it, wall clock, from start to exit. */
public final class ProcessRun {

    private ProcessRun() {
    }

    /**
     * Runs the command with its output (both streams) going to {@code log}, and checks that it
     * exited 0 and wrote {@code output}.
     *
     * @return the wall time in nanoseconds
     * @throws IOException if it could not start, failed, or wrote no image (the message has the log's end)
     */
    public static long time(List<String> command, Path output, Path log) throws IOException {
        Files.deleteIfExists(output);
        ProcessBuilder builder = new ProcessBuilder(command).redirectErrorStream(true)
                .redirectOutput(log.toFile());
        long start = System.nanoTime();
        Process process = builder.start();
        int exit;
        try {
            exit = process.waitFor();
        } catch (InterruptedException e) {
            process.destroyForcibly();
            Thread.currentThread().interrupt();
            throw new IOException("interrupted", e);
        }
        long nanos = System.nanoTime() - start;
        if (exit != 0 || !Files.isRegularFile(output)) {
            throw new IOException((exit != 0 ? "exit code " + exit : "no image written") + " from: "
                    + String.join(" ", command) + "\n" + tail(log));
        }
        return nanos;
    }

    /** The last 15 lines of a log, for an error message. */
    public static String tail(Path log) {
        try {
            List<String> lines = Files.readAllLines(log);
            return String.join("\n", lines.subList(Math.max(0, lines.size() - 15), lines.size()));
        } catch (IOException e) {
            return "(no log: " + e.getMessage() + ")";
        }
    }
}
