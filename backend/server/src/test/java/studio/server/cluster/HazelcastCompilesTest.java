package studio.server.cluster;

import static org.assertj.core.api.Assertions.assertThat;

import java.lang.management.ManagementFactory;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import javax.management.ObjectName;

import org.junit.jupiter.api.Test;

/**
 * The compiler directive a clustered member adds before its Hazelcast member starts: on this JVM
 * (HotSpot, 17 or later) it is taken, it excludes C2 and not C1 for Hazelcast's classes alone, and
 * a second member in the same JVM (the cluster tests') adds no second directive.
 */
class HazelcastCompilesTest {

    @Test
    void theJvmTakesItOnceWithC2ExcludedForHazelcastAlone() throws Exception {
        assertThat(HazelcastCompiles.keepOutOfC2()).isTrue();
        assertThat(HazelcastCompiles.keepOutOfC2()).isTrue();

        String stack = directives();
        Matcher ours = Pattern.compile("matching: com/hazelcast/\\*\\.\\*").matcher(stack);
        assertThat(ours.find()).as("the directive in the JVM's stack:%n%s", stack).isTrue();
        assertThat(ours.find()).as("added once").isFalse();

        // the directive's two blocks: C1's not enabled (C1 compiles Hazelcast as before), C2's excludes
        String directive = stack.substring(stack.indexOf("matching: com/hazelcast/"), stack.indexOf("matching: *.*"));
        String c1 = directive.substring(directive.indexOf("c1 directives:"), directive.indexOf("c2 directives:"));
        String c2 = directive.substring(directive.indexOf("c2 directives:"));
        assertThat(c1).contains("Enable:false");
        assertThat(c2).contains("Enable:true").contains("Exclude:true");
        // and the default below it, for every other method, excludes nothing
        String fallback = stack.substring(stack.indexOf("matching: *.*"));
        assertThat(fallback).doesNotContain("Exclude:true");
    }

    private static String directives() throws Exception {
        return String.valueOf(ManagementFactory.getPlatformMBeanServer().invoke(
                new ObjectName("com.sun.management:type=DiagnosticCommand"), "compilerDirectivesPrint",
                new Object[] {new String[0]}, new String[] {String[].class.getName()}));
    }
}
