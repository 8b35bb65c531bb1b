package studio.server.scene;

/**
 * Configurable limits on what one scene may ask for (studio.limits.* in application.properties).
 *
 * @param maxTriangles all meshes' triangles together
 * @param maxBodyBytes largest request body the API reads (inline meshes count: about 70 bytes a triangle)
 */
public record SceneLimits(int maxWidth, int maxHeight, int maxSamples, int maxDepth, int maxObjects, int maxLights,
                          int maxTriangles, long maxBodyBytes) {

    public static final SceneLimits DEFAULTS = new SceneLimits(4096, 4096, 1024, 16, 100_000, 100, 2_000_000,
            32L * 1024 * 1024);
}
