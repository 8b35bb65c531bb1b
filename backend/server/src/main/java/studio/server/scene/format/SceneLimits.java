package studio.server.scene.format;

/**
 * Configurable limits on what one scene may ask for (studio.limits.* in application.properties).
 *
 * @param maxTriangles    all meshes' triangles together
 * @param maxBodyBytes    largest request body the API reads (inline meshes count: about 70 bytes a triangle)
 * @param maxPixelSamples the render budget: width x height x samples per pixel (the most samples a render may
 *                        take; adaptive sampling counts at its maximum, since that is what it may spend)
 */
public record SceneLimits(int maxWidth, int maxHeight, int maxSamples, int maxDepth, int maxObjects, int maxLights,
                          int maxTriangles, long maxBodyBytes, long maxPixelSamples) {

    public static final SceneLimits DEFAULTS = new SceneLimits(4096, 4096, 1024, 16, 100_000, 100, 2_000_000,
            32L * 1024 * 1024, 1L << 28);

    /** Without a render budget beyond the separate limits. */
    public SceneLimits(int maxWidth, int maxHeight, int maxSamples, int maxDepth, int maxObjects, int maxLights,
                       int maxTriangles, long maxBodyBytes) {
        this(maxWidth, maxHeight, maxSamples, maxDepth, maxObjects, maxLights, maxTriangles, maxBodyBytes,
                Long.MAX_VALUE);
    }
}
