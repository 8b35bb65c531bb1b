package studio.server.cluster;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import javax.management.JMException;
import javax.management.ObjectName;

import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Keeps Hazelcast's own code out of C2 in a clustered member: C1 compiles it. C2 compiled Hazelcast's
 * operation, network and response loops, each with its callees inlined, during a member's first jobs,
 * on the cores that render their tiles, while under C1 its threads spend the same CPU a job
 * (docs/cluster.md, "The warm job's compiles"; {@code scripts/cluster-cpu.py}).
 *
 * <p>A compiler directive added through HotSpot's {@code Compiler.directives_add} command (its MBean),
 * once a JVM, before the member starts; a service without a cluster runs no Hazelcast code and is left
 * alone. A JVM that refuses the command compiles as before: that is logged and the member starts.
 */
final class HazelcastCompiles {

    private static final Logger log = LoggerFactory.getLogger(HazelcastCompiles.class);
    /** Every class of Hazelcast's packages (its shaded libraries too): C2 excluded, C1 as usual. */
    static final String DIRECTIVE = "[{ match: [\"com/hazelcast/*.*\"], c2: { Exclude: true } }]";
    private static boolean added;

    private HazelcastCompiles() {
    }

    /** Adds the directive, once a JVM (the directives' stack is bounded); true if this JVM has it. */
    static synchronized boolean keepOutOfC2() {
        if (!added) {
            added = add();
        }
        return added;
    }

    private static boolean add() {
        Path file = null;
        try {
            file = Files.createTempFile("studio-hazelcast-", ".json"); // the command reads a file only
            Files.writeString(file, DIRECTIVE, StandardCharsets.UTF_8);
            Object answer = ManagementFactory.getPlatformMBeanServer().invoke(
                    new ObjectName("com.sun.management:type=DiagnosticCommand"), "compilerDirectivesAdd",
                    new Object[] {new String[] {file.toString()}}, new String[] {String[].class.getName()});
            String text = String.valueOf(answer).strip();
            if (!text.contains("added")) {
                log.info("Hazelcast's code stays with the JVM's usual compilers: the directive was refused ({})", text);
                return false;
            }
            log.info("Hazelcast's code is compiled by C1 alone, by a compiler directive; the rest as usual");
            return true;
        } catch (JMException | IOException | RuntimeException e) {
            log.info("Hazelcast's code stays with the JVM's usual compilers: {}", e.toString());
            return false;
        } finally {
            if (file != null) {
                try {
                    Files.deleteIfExists(file);
                } catch (IOException e) {
                    log.debug("could not delete {}: {}", file, e.toString());
                }
            }
        }
    }
}
