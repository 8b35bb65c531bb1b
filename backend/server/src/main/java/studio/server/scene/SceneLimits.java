package studio.server.scene;

/**
 * Configurable limits on what one scene may ask for (studio.limits.* in application.properties).
 *
 * @param maxBodyBytes largest request body the API reads
 */
public record SceneLimits(int maxWidth, int maxHeight, int maxSamples, int maxDepth, int maxObjects, int maxLights,
                          long maxBodyBytes) {

    public static final SceneLimits DEFAULTS = new SceneLimits(4096, 4096, 1024, 16, 10_000, 100, 2L * 1024 * 1024);
}
