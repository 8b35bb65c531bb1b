package studio.engine.accel;

/**
 * The ray/box test of a {@link WideBvh} node: all eight of its children's boxes against one
 * {@link WideRay} at once. Two implementations give the same bits: {@link ScalarBoxTest} in plain
 * Java, and a Vector API one where the JVM has {@code jdk.incubator.vector}; {@link WideBoxTests}
 * picks one at start-up, as Lucene's {@code VectorizationProvider} does.
 */
public interface WideBoxTest {

    /**
     * Tests the eight boxes of the node at {@code boxes[base .. base + 47]} ({@code base} =
     * {@link WideBvh#FLOATS} times the node's index): returns a mask with bit k set when the ray
     * meets lane k's box for some t in [0, limit], and writes lane k's entry distance (0 when the
     * ray starts inside) to {@code entry[k]} for every lane (meaningful for the set bits only).
     * {@code limit} comes from {@link WideRay#limit}. Conservative: every box the double
     * {@link Slab} test meets with the same ray and limit is kept. Allocates nothing.
     */
    int test(float[] boxes, int base, WideRay ray, float limit, float[] entry);
}
