package studio.engine.accel;

/**
 * One thread's working memory for one level of a {@link Traversal}'s wide walk (the scene's tree,
 * or a mesh's inside it): the ray set up for the float box test, the eight entry distances a node
 * test writes, and the stack of nodes waiting with their entry distances. Reused for every ray, so
 * the walk allocates nothing.
 */
public final class WideScratch {

    final WideRay ray = new WideRay();
    final float[] entry = new float[WideBvh.WIDTH];
    final int[] stack = new int[WideBvh.STACK_SIZE];
    final float[] stackEntry = new float[WideBvh.STACK_SIZE];

    /**
     * A scratch when this JVM's traversals walk wide trees ({@link WideBoxTests#vectorized}), else
     * null: the binary walk needs none, so a scalar JVM carries none.
     */
    public static WideScratch ifUsed() {
        return Traversal.WIDE ? new WideScratch() : null;
    }
}
