package studio.server.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;

/**
 * {@code studio.jar train SCENE.json...}: renders each scene file as it stands, one after the
 * other in this one JVM, through {@link RenderCommand} (reading, validation, rendering and the PNG
 * file), and throws the images away. Exit code as the render command's: the first failure stops it.
 *
 * <p>{@code bin/studio} runs it once to record its start-up cache, whose method profiles are this
 * run's. Profiles from one kind of scene make the JIT compile the others' paths as never taken:
 * trained on a scene of many objects alone (light buffers, pixel lists), a still life's shadow
 * rays, which search the tree, deoptimized the tree's box test and shadow search in the first
 * half second of every render. So the training renders a scene of each kind the engine treats apart.
 */
public final class TrainCommand {

    static final String USAGE = "usage: java -jar studio.jar train SCENE.json...";

    private TrainCommand() {
    }

    public static int run(String[] args, PrintStream out, PrintStream err) {
        return run(args, out, err, null);
    }

    /** {@link #run(String[], PrintStream, PrintStream)} with the images in a new directory in {@code parent} (null: the system's). */
    static int run(String[] args, PrintStream out, PrintStream err, Path parent) {
        if (args.length == 1 && (args[0].equals("--help") || args[0].equals("-h"))) {
            out.println(USAGE);
            return RenderCommand.OK;
        }
        if (args.length == 0 || Stream.of(args).anyMatch(a -> a.startsWith("-"))) {
            err.println(USAGE);
            return RenderCommand.INVALID;
        }
        Path images;
        try {
            images = parent != null ? Files.createTempDirectory(parent, "studio-train")
                    : Files.createTempDirectory("studio-train");
        } catch (IOException e) {
            err.println("error: cannot make a directory for the images: " + e.getMessage());
            return RenderCommand.IO_ERROR;
        }
        try {
            for (int i = 0; i < args.length; i++) {
                String image = images.resolve(i + ".png").toString();
                int code = RenderCommand.run(new String[] {args[i], "-o", image, "--quiet"}, out, err);
                if (code != RenderCommand.OK) {
                    return code;
                }
            }
            return RenderCommand.OK;
        } finally {
            delete(images, err);
        }
    }

    /** Removes the images and their directory; a failure is only reported, the renders are done. */
    private static void delete(Path directory, PrintStream err) {
        try (Stream<Path> files = Files.list(directory)) {
            for (Path file : (Iterable<Path>) files::iterator) {
                Files.deleteIfExists(file);
            }
            Files.deleteIfExists(directory);
        } catch (IOException e) {
            err.println("warning: cannot remove " + directory + ": " + e.getMessage());
        }
    }
}
