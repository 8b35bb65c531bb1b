package studio.server.scene.format;

/**
 * The bound on every coordinate of a scene (positions, centres, points, the camera and its target),
 * in metres: |x| ≤ 10¹². The engine renders a scene moved by 10¹² on each axis as at the origin
 * (docs/robustness.md, SELF-02: SelfIntersectionTest, TransformInvarianceTest); beyond that nothing
 * is tested (an object at 1e300, once accepted, was silently not drawn).
 */
public final class Coordinates {

    /** The largest coordinate, as Bean Validation's {@code @DecimalMax} takes it. */
    public static final String MAX = "1e12";

    /** The smallest coordinate, as {@code @DecimalMin} takes it. */
    public static final String MIN = "-1e12";

    private Coordinates() {
    }
}
