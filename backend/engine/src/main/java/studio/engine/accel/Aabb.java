package studio.engine.accel;

/**
 * An axis-aligned bounding box in world space, used in setup code: what a shape reports as its
 * bounds, and what the BVH builder reads. {@link #UNBOUNDED} stands for shapes without finite
 * bounds (planes), which are kept out of a BVH.
 */
public record Aabb(double minX, double minY, double minZ, double maxX, double maxY, double maxZ) {

    public static final Aabb UNBOUNDED = new Aabb(Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY,
            Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY);

    public Aabb {
        if (Double.isNaN(minX) || Double.isNaN(minY) || Double.isNaN(minZ)
                || Double.isNaN(maxX) || Double.isNaN(maxY) || Double.isNaN(maxZ)
                || !(minX <= maxX && minY <= maxY && minZ <= maxZ)) {
            throw new IllegalArgumentException("box bounds must satisfy min <= max on every axis");
        }
    }

    /** Whether every bound is finite, so the box can go into a BVH. */
    public boolean isBounded() {
        return Double.isFinite(minX) && Double.isFinite(minY) && Double.isFinite(minZ)
                && Double.isFinite(maxX) && Double.isFinite(maxY) && Double.isFinite(maxZ);
    }

    /**
     * The box grown on each side by {@code relative} times the largest absolute coordinate on that
     * axis plus one ulp-sized step: used by shapes whose exact extent is computed with rounding.
     */
    public Aabb padded(double relative) {
        double px = relative * Math.max(Math.abs(minX), Math.abs(maxX));
        double py = relative * Math.max(Math.abs(minY), Math.abs(maxY));
        double pz = relative * Math.max(Math.abs(minZ), Math.abs(maxZ));
        return new Aabb(Math.nextDown(minX - px), Math.nextDown(minY - py), Math.nextDown(minZ - pz),
                Math.nextUp(maxX + px), Math.nextUp(maxY + py), Math.nextUp(maxZ + pz));
    }

    /**
     * The distance from (x, y, z) to the box stored at {@code boxes[o .. o+5]} (min x, y, z, max
     * x, y, z), 0 inside it: rounded, so callers that need a bound below it shrink it.
     */
    public static double distance(double[] boxes, int o, double x, double y, double z) {
        double dx = Math.max(0, Math.max(boxes[o] - x, x - boxes[o + 3]));
        double dy = Math.max(0, Math.max(boxes[o + 1] - y, y - boxes[o + 4]));
        double dz = Math.max(0, Math.max(boxes[o + 2] - z, z - boxes[o + 5]));
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    /** Writes minX, minY, minZ, maxX, maxY, maxZ into {@code out} at {@code offset}. */
    public void copyTo(double[] out, int offset) {
        out[offset] = minX;
        out[offset + 1] = minY;
        out[offset + 2] = minZ;
        out[offset + 3] = maxX;
        out[offset + 4] = maxY;
        out[offset + 5] = maxZ;
    }
}
