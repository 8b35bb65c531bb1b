package studio.server.cluster;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Set;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;

/** A coordinator reads its claims when a member left, and otherwise only every {@value LostCheck#BACKSTOP_MILLIS} ms. */
class LostCheckTest {

    private static final long SECOND = TimeUnit.SECONDS.toNanos(1);

    @Test
    void readsTheClaimsOnlyAtTheBackstopWhileNoMemberLeaves() {
        LostCheck check = new LostCheck(Set.of("a", "b"), 0);

        for (long t = 1; t <= 4; t++) {
            assertThat(check.due(t * SECOND, false, Set.of("a", "b"))).as("a look at %d s", t).isFalse();
        }
        assertThat(check.due(4 * SECOND, false, Set.of("a", "b", "c"))).as("a member joined").isFalse();
        assertThat(check.due(5 * SECOND + 1, false, Set.of("a", "b", "c"))).as("the backstop").isTrue();
        assertThat(check.due(6 * SECOND, false, Set.of("a", "b", "c"))).isFalse();
    }

    @Test
    void readsTheClaimsAtTheNextLookAfterAMemberLeft() {
        LostCheck check = new LostCheck(Set.of("a", "b", "c"), 0);

        assertThat(check.due(SECOND, false, Set.of("a", "c"))).as("b is gone, unheard").isTrue();
        assertThat(check.due(2 * SECOND, false, Set.of("a", "c"))).isFalse();
        assertThat(check.due(2 * SECOND, true, Set.of("a", "c"))).as("a member left, heard").isTrue();
        assertThat(check.due(3 * SECOND, false, Set.of("a", "d"))).as("c gone while d joined").isTrue();
    }
}
