package studio.server.scene.compiling;

import static studio.server.scene.compiling.FormatValues.or;

import java.util.Locale;

import studio.engine.render.RenderSettings;
import studio.engine.sampler.RegularSampler;
import studio.engine.sampler.Sampler;
import studio.engine.sampler.SobolSampler;
import studio.server.scene.format.ImageDto;
import studio.server.scene.format.RenderDto;
import studio.server.scene.format.SceneDefaults;
import studio.server.scene.format.SceneLimits;

/**
 * A scene's "image" and "render" fields with their defaults, checked against the server's limits
 * and its render budget: what the engine's {@link RenderSettings} are made of, and how to write the
 * image. The sampler is null when a problem was found.
 *
 * @param format  "png" or "jpg"
 * @param quality JPEG quality in [0, 1]
 */
record RenderMapping(int width, int height, Sampler sampler, int maxDepth, long seed, double adaptive, String format,
                     double quality) {

    static RenderMapping of(ImageDto imageDto, RenderDto renderDto, SceneLimits limits, MappingProblems problems) {
        ImageDto image = imageDto != null ? imageDto : new ImageDto(null, null, null, null);
        int width = or(image.width(), SceneDefaults.WIDTH);
        int height = or(image.height(), SceneDefaults.HEIGHT);
        problems.atMost("image.width", width, limits.maxWidth());
        problems.atMost("image.height", height, limits.maxHeight());

        RenderDto render = renderDto != null ? renderDto : new RenderDto(null, null, null, null);
        int samples = or(render.samples(), SceneDefaults.SAMPLES);
        int maxDepth = or(render.maxDepth(), SceneDefaults.MAX_DEPTH);
        String samplerName = or(render.sampler(), SceneDefaults.SAMPLER);
        problems.atMost("render.samples", samples, limits.maxSamples());
        problems.atMost("render.maxDepth", maxDepth, limits.maxDepth());
        long pixelSamples = (long) width * height * samples;
        if (pixelSamples > limits.maxPixelSamples() && width <= limits.maxWidth() && height <= limits.maxHeight()
                && samples <= limits.maxSamples()) {
            problems.add("render.samples", String.format(Locale.ROOT, "%d x %d pixels x %d samples = %,d "
                    + "samples, more than this server's render budget of %,d samples per render "
                    + "(studio.limits.max-pixel-samples); lower render.samples or the image size", width, height,
                    samples, pixelSamples, limits.maxPixelSamples()));
        }
        Sampler sampler = problems.attempt("render.samples", () -> Sampler.of(samplerName, samples));
        // adaptive sampling is the default with sobol, the method that wins the speed-against-accuracy chart
        double adaptive = or(render.adaptive(), sampler instanceof SobolSampler ? SceneDefaults.ADAPTIVE : 0.0);
        if (adaptive > 0 && sampler instanceof RegularSampler) {
            problems.add("render.adaptive", "cannot be used with the regular sampler, which would put every batch "
                    + "of samples on the same grid; choose another sampler or set it to 0");
        }
        return new RenderMapping(width, height, sampler, maxDepth, or(render.seed(), SceneDefaults.SEED), adaptive,
                or(image.format(), SceneDefaults.FORMAT), or(image.quality(), SceneDefaults.JPEG_QUALITY));
    }

    /** @param threads worker threads for the render (0: all cores); the server's, not part of the scene */
    RenderSettings settings(int threads) {
        return new RenderSettings(width, height, sampler, maxDepth, threads, seed,
                RenderSettings.DEFAULT_MIN_PATH_WEIGHT, adaptive);
    }
}
