package studio.engine.material;

/** Fresnel reflectance of a smooth dielectric interface and Snell refraction. */
public final class Fresnel {

    private Fresnel() {
    }

    /**
     * Unpolarised reflectance for light arriving at cosine {@code cosI} (clamped to [0, 1]) from a
     * medium of index {@code etaI} into one of {@code etaT}. Exact, not Schlick: leaving glass near
     * the critical angle it rises continuously to 1, and it is 1 beyond (total internal reflection).
     */
    public static double reflectance(double cosI, double etaI, double etaT) {
        cosI = Math.min(1, Math.max(0, cosI));
        double sinI = Math.sqrt(Math.max(0, 1 - cosI * cosI));
        double sinT = etaI / etaT * sinI;
        if (sinT >= 1) {
            return 1;
        }
        double cosT = Math.sqrt(Math.max(0, 1 - sinT * sinT));
        double parallel = (etaT * cosI - etaI * cosT) / (etaT * cosI + etaI * cosT);
        double perpendicular = (etaI * cosI - etaT * cosT) / (etaI * cosI + etaT * cosT);
        return (parallel * parallel + perpendicular * perpendicular) / 2;
    }
}
