package studio.bench;

import java.util.Arrays;

/**
 * {@code java -jar studio-bench.jar peers [...]}: the peer benchmark ({@link PeersCommand}).
 * Sunflow's side runs as its own process through {@link SunflowRender}.
 */
public final class BenchMain {

    private BenchMain() {
    }

    public static void main(String[] args) {
        if (args.length > 0 && args[0].equals("peers")) {
            System.exit(PeersCommand.run(Arrays.copyOfRange(args, 1, args.length), System.out, System.err));
        }
        System.err.println("usage: java -jar studio-bench.jar peers [--help]");
        System.exit(2);
    }
}
