package studio.bench;

import java.util.Arrays;

/**
 * {@code java -jar studio-bench.jar accuracy|peers|jmh|scaling|kernel|wide [...]}: the samplers' speed against
 * accuracy ({@link studio.bench.accuracy.BenchCommand}), the peer benchmark ({@link PeersCommand}),
 * the JMH micro-benchmarks in {@code studio.bench.jmh} (the arguments go to JMH's own command line,
 * {@code org.openjdk.jmh.Main}), render time against scene size ({@link ScalingCommand}) and the ray
 * kernel's throughput beside Embree's ({@link studio.bench.kernel.KernelCommand}) and the binary
 * against the wide BVH walk ({@link WideCommand}).
 * Sunflow's side of the peer benchmark runs as its own process through {@link SunflowRender}.
 */
public final class BenchMain {

    static final String USAGE = """
            usage: java -jar studio-bench.jar accuracy [--help]   the samplers' speed against accuracy (the README's chart)
                   java -jar studio-bench.jar peers [--help]      ours against POV-Ray and Sunflow
                   java -jar studio-bench.jar jmh [JMH options]   micro-benchmarks (-h: JMH's options, -l: the list)
                   java -jar studio-bench.jar scaling [--help]    render time against object count
                   java -jar studio-bench.jar kernel [--help]     rays a second of the bare kernel (beside Embree's)
                   java -jar studio-bench.jar wide [ROUNDS]       the binary against the wide BVH walk, CPU time a ray""";

    private BenchMain() {
    }

    public static void main(String[] args) throws Exception {
        String command = args.length > 0 ? args[0] : "";
        String[] rest = args.length > 0 ? Arrays.copyOfRange(args, 1, args.length) : args;
        switch (command) {
            case "accuracy" -> System.exit(studio.bench.accuracy.BenchCommand.run(rest, System.out, System.err));
            case "peers" -> System.exit(PeersCommand.run(rest, System.out, System.err));
            case "scaling" -> System.exit(ScalingCommand.run(rest, System.out, System.err));
            case "kernel" -> System.exit(studio.bench.kernel.KernelCommand.run(rest, System.out, System.err));
            case "wide" -> System.exit(WideCommand.run(rest, System.out, System.err));
            // JMH exits by itself on errors; it forks the benchmarks with this JVM's class path, which is
            // this jar and, through its manifest, lib/
            case "jmh" -> {
                org.openjdk.jmh.Main.main(rest);
                System.exit(0);
            }
            default -> {
                System.err.println(USAGE);
                System.exit(2);
            }
        }
    }
}
