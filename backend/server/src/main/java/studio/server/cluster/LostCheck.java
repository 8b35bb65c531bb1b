package studio.server.cluster;

import java.util.Set;
import java.util.concurrent.TimeUnit;

/**
 * When a job's coordinator reads its claims to find the tiles of members that left ({@link TileFarm}): at
 * its next look after a member left (heard, or missing from the members it saw at its last look), and
 * otherwise at most every {@value #BACKSTOP_MILLIS} ms. Reading the claims is a query of every member's
 * partitions; done every second it took the owner's and the workers' JIT into the query engine during
 * every job (the compilations of two pinned members' warm job, docs/cluster.md, "Where two members' CPU goes").
 */
final class LostCheck {

    /** The claims are read at least this often even when no member left. */
    static final long BACKSTOP_MILLIS = 5_000;

    private Set<String> seen;
    private long nextRead;

    /** @param alive the members alive when the job's render starts */
    LostCheck(Set<String> alive, long nowNanos) {
        this.seen = alive;
        this.nextRead = nowNanos + TimeUnit.MILLISECONDS.toNanos(BACKSTOP_MILLIS);
    }

    /**
     * True if the claims should be read now.
     *
     * @param left  a member left since the last look (a membership event)
     * @param alive the members alive now
     */
    boolean due(long nowNanos, boolean left, Set<String> alive) {
        boolean gone = left || !alive.containsAll(seen);
        seen = alive;
        if (gone || nowNanos - nextRead > 0) {
            nextRead = nowNanos + TimeUnit.MILLISECONDS.toNanos(BACKSTOP_MILLIS);
            return true;
        }
        return false;
    }
}
