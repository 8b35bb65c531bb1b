package studio.server;

import java.util.Arrays;

import org.springframework.boot.SpringApplication;
import org.springframework.boot.autoconfigure.SpringBootApplication;

import studio.server.bench.BenchCommand;
import studio.server.cli.RenderCommand;

/**
 * The studio: {@code java -jar studio.jar} starts the service and the editor on port 8080;
 * {@code java -jar studio.jar render SCENE.json -o OUT.png} renders a file without starting it;
 * {@code java -jar studio.jar bench} measures the samplers' speed against accuracy (see {@link BenchCommand}).
 */
@SpringBootApplication
public class StudioApplication {

    public static void main(String[] args) {
        if (args.length > 0 && args[0].equals("render")) {
            System.setProperty("logback.configurationFile", "logback-cli.xml");
            System.exit(RenderCommand.run(Arrays.copyOfRange(args, 1, args.length), System.out, System.err));
        }
        if (args.length > 0 && args[0].equals("bench")) {
            System.setProperty("logback.configurationFile", "logback-cli.xml");
            System.exit(BenchCommand.run(Arrays.copyOfRange(args, 1, args.length), System.out, System.err));
        }
        SpringApplication.run(StudioApplication.class, args);
    }
}
