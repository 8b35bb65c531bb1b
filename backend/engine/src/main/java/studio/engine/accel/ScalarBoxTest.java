package studio.engine.accel;

import java.util.Arrays;

/**
 * {@link WideBoxTest} in plain Java, lane by lane: the path of every JVM without the Vector API,
 * and the reference the vector one is tested against. Each lane takes the same float operations in
 * the same order as a vector lane (subtract the origin, multiply by the inverse direction, widen
 * the far distance, then comparisons that a NaN fails), so both give the same bits.
 */
public final class ScalarBoxTest implements WideBoxTest {

    @Override
    public int test(float[] boxes, int base, WideRay ray, float limit, float[] entry) {
        if (ray.acceptAll) {
            return acceptAll(entry);
        }
        float ix = ray.ix, iy = ray.iy, iz = ray.iz, w = WideRay.FAR_WIDENING;
        float nox = ray.nearOx, noy = ray.nearOy, noz = ray.nearOz, fox = ray.farOx, foy = ray.farOy, foz = ray.farOz;
        int nx = base + ray.nearX, ny = base + ray.nearY, nz = base + ray.nearZ;
        int fx = base + ray.farX, fy = base + ray.farY, fz = base + ray.farZ;
        int mask = 0;
        for (int k = 0; k < WideBvh.WIDTH; k++) {
            float tNear = 0, tFar = limit;
            float near = (boxes[nx + k] - nox) * ix, far = (boxes[fx + k] - fox) * ix * w;
            tNear = near > tNear ? near : tNear;
            tFar = far < tFar ? far : tFar;
            near = (boxes[ny + k] - noy) * iy;
            far = (boxes[fy + k] - foy) * iy * w;
            tNear = near > tNear ? near : tNear;
            tFar = far < tFar ? far : tFar;
            near = (boxes[nz + k] - noz) * iz;
            far = (boxes[fz + k] - foz) * iz * w;
            tNear = near > tNear ? near : tNear;
            tFar = far < tFar ? far : tFar;
            entry[k] = tNear;
            mask |= (tNear <= tFar ? 1 : 0) << k;
        }
        return mask;
    }

    /** The answer for a ray the float test cannot bound ({@link WideRay#acceptAll}): every lane, entered at 0. */
    static int acceptAll(float[] entry) {
        Arrays.fill(entry, 0, WideBvh.WIDTH, 0f);
        return WideBvh.ALL_LANES;
    }
}
