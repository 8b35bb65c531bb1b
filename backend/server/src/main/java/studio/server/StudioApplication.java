package studio.server;

import java.util.Arrays;

import org.springframework.boot.SpringApplication;
import org.springframework.boot.autoconfigure.SpringBootApplication;

import studio.server.cli.RenderCommand;
import studio.server.cli.TrainCommand;

/**
 * The studio: {@code java -jar studio.jar} starts the service and the editor on port 8080;
 * {@code java -jar studio.jar render SCENE.json -o OUT.png} renders a file without starting it;
 * {@code java -jar studio.jar train SCENE.json...} renders files and keeps nothing (bin/studio's
 * training run, see {@link TrainCommand}).
 * The benchmarks are not part of the service: they are in {@code backend/bench} ({@code studio-bench.jar}).
 */
@SpringBootApplication
public class StudioApplication {

    /** Held, so that its level stays set (java.util.logging keeps loggers only weakly). */
    private static final java.util.logging.Logger HIBERNATE_LOG = java.util.logging.Logger.getLogger("org.hibernate");

    public static void main(String[] args) {
        if (args.length > 0 && args[0].equals("render")) {
            quietCommandLineLogging();
            System.exit(RenderCommand.run(Arrays.copyOfRange(args, 1, args.length), System.out, System.err));
        }
        if (args.length > 0 && args[0].equals("train")) {
            quietCommandLineLogging();
            System.exit(TrainCommand.run(Arrays.copyOfRange(args, 1, args.length), System.out, System.err));
        }
        SpringApplication.run(StudioApplication.class, args);
    }

    /**
     * The command lines print their own messages; libraries only warn. Bean Validation logs through
     * java.util.logging here rather than Logback: starting Logback (500 classes and an XML parser)
     * was a fifth of a small render's start-up.
     */
    private static void quietCommandLineLogging() {
        System.setProperty("logback.configurationFile", "logback-cli.xml");
        System.setProperty("org.jboss.logging.provider", "jdk");
        HIBERNATE_LOG.setLevel(java.util.logging.Level.WARNING);
    }
}
