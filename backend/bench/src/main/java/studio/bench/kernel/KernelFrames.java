package studio.bench.kernel;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;

import studio.engine.scene.Scene;

/**
 * Whole frames of {@link PrimaryShadowRays} on one or more threads (each a band of rows, as
 * embree_rays splits them), each timed twice: by the wall clock around the frame, thread starts
 * included, and by the CPU time of the tracing threads, summed, which a machine shared with other
 * work disturbs far less (a descheduled thread's wait is not counted). Every frame must count the
 * same hits and blocked shadow rays, or the kernel is not deterministic and the timing means nothing.
 */
final class KernelFrames {

    private final PrimaryShadowRays[] workers;
    private final int width, height;
    private final byte[] mask;
    private long hits = -1, occluded = -1;
    /** The CPU time of the last frame. */
    private long cpuNanos;

    KernelFrames(Scene scene, int width, int height, int threads) {
        this.width = width;
        this.height = height;
        mask = new byte[width * height];
        workers = new PrimaryShadowRays[threads];
        for (int i = 0; i < threads; i++) {
            workers[i] = new PrimaryShadowRays(scene, width, height, mask);
        }
    }

    /** Primary rays that hit, in every frame. */
    long hits() {
        return hits;
    }

    /** Shadow rays that were blocked, in every frame. */
    long occluded() {
        return occluded;
    }

    /**
     * Writes the last frame's outcome per pixel as a binary PGM: black where the camera ray missed,
     * white where it hit a lit point, grey where the shadow ray was blocked (embree_rays writes the same).
     */
    void writeMask(Path file) throws IOException {
        byte[] header = ("P5\n" + width + " " + height + "\n255\n").getBytes(StandardCharsets.US_ASCII);
        try (OutputStream out = Files.newOutputStream(file)) {
            out.write(header);
            out.write(mask);
        }
    }

    /** Traces one frame; returns its wall time in nanoseconds. */
    long frame() throws InterruptedException {
        int n = workers.length;
        long start = System.nanoTime();
        if (n == 1) {
            workers[0].trace(0, height);
        } else {
            Thread[] threads = new Thread[n];
            for (int i = 0; i < n; i++) {
                PrimaryShadowRays w = workers[i];
                int first = i * height / n, end = (i + 1) * height / n;
                threads[i] = new Thread(() -> w.trace(first, end), "kernel-" + i);
                threads[i].start();
            }
            for (Thread t : threads) {
                t.join();
            }
        }
        long nanos = System.nanoTime() - start;
        long h = 0, o = 0, cpu = 0;
        for (PrimaryShadowRays w : workers) {
            h += w.hits;
            o += w.occluded;
            cpu += w.cpuNanos;
        }
        if (hits >= 0 && (h != hits || o != occluded)) {
            throw new IllegalStateException("frames differ: " + h + " hits, " + o + " blocked, against " + hits
                    + " and " + occluded + " before");
        }
        hits = h;
        occluded = o;
        cpuNanos = cpu;
        return nanos;
    }

    /** The first frame's wall time, and the timed frames' wall and CPU times, each sorted, in nanoseconds. */
    record Times(long first, long[] wall, long[] cpu) {

        static long median(long[] sorted) {
            int n = sorted.length;
            return n % 2 == 1 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
        }
    }

    /**
     * Frames until {@code warmUpNanos} have passed (at least 3, so the JIT has compiled the loop),
     * then {@code timed} frames.
     */
    Times measure(long warmUpNanos, int timed) throws InterruptedException {
        long first = frame();
        long spent = first;
        for (int i = 1; i < 3 || spent < warmUpNanos; i++) {
            spent += frame();
        }
        long[] wall = new long[timed], cpu = new long[timed];
        for (int i = 0; i < timed; i++) {
            wall[i] = frame();
            cpu[i] = cpuNanos;
        }
        Arrays.sort(wall);
        Arrays.sort(cpu);
        return new Times(first, wall, cpu);
    }
}
