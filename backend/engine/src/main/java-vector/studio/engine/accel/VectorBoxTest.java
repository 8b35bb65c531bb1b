package studio.engine.accel;

import jdk.incubator.vector.FloatVector;
import jdk.incubator.vector.VectorOperators;
import jdk.incubator.vector.VectorSpecies;

/**
 * {@link WideBoxTest} through the Vector API: a node's eight lanes in one 256-bit float vector per
 * bound, the same operations as {@link ScalarBoxTest} lane for lane (so the same bits), with the
 * NaN-ignoring comparisons as blends. Loaded only by {@link WideBoxTests}, by name; compiled apart
 * (src/main/java-vector, with the incubator module) so the rest of the engine builds for JDK 17.
 */
final class VectorBoxTest implements WideBoxTest {

    private static final VectorSpecies<Float> LANES = FloatVector.SPECIES_256;

    VectorBoxTest() {
    }

    @Override
    public int test(float[] boxes, int base, WideRay ray, float limit, float[] entry) {
        if (ray.acceptAll) {
            return ScalarBoxTest.acceptAll(entry);
        }
        FloatVector tNear = FloatVector.zero(LANES);
        FloatVector tFar = FloatVector.broadcast(LANES, limit);

        FloatVector near = FloatVector.fromArray(LANES, boxes, base + ray.nearX).sub(ray.nearOx).mul(ray.ix);
        FloatVector far = FloatVector.fromArray(LANES, boxes, base + ray.farX).sub(ray.farOx).mul(ray.ix).mul(WideRay.FAR_WIDENING);
        tNear = tNear.blend(near, near.compare(VectorOperators.GT, tNear));
        tFar = tFar.blend(far, far.compare(VectorOperators.LT, tFar));

        near = FloatVector.fromArray(LANES, boxes, base + ray.nearY).sub(ray.nearOy).mul(ray.iy);
        far = FloatVector.fromArray(LANES, boxes, base + ray.farY).sub(ray.farOy).mul(ray.iy).mul(WideRay.FAR_WIDENING);
        tNear = tNear.blend(near, near.compare(VectorOperators.GT, tNear));
        tFar = tFar.blend(far, far.compare(VectorOperators.LT, tFar));

        near = FloatVector.fromArray(LANES, boxes, base + ray.nearZ).sub(ray.nearOz).mul(ray.iz);
        far = FloatVector.fromArray(LANES, boxes, base + ray.farZ).sub(ray.farOz).mul(ray.iz).mul(WideRay.FAR_WIDENING);
        tNear = tNear.blend(near, near.compare(VectorOperators.GT, tNear));
        tFar = tFar.blend(far, far.compare(VectorOperators.LT, tFar));

        tNear.intoArray(entry, 0);
        return (int) tNear.compare(VectorOperators.LE, tFar).toLong();
    }
}
