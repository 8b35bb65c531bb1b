package studio.server.scene.format;

import jakarta.validation.constraints.DecimalMax;
import jakarta.validation.constraints.Pattern;
import jakarta.validation.constraints.Positive;
import jakarta.validation.constraints.PositiveOrZero;

/**
 * How to sample: sampler name, samples per pixel (with adaptive sampling: the most a pixel takes),
 * recursion depth, the noise seed, and the adaptive-sampling threshold (a relative error in [0, 1];
 * 0: off; absent: {@link SceneDefaults#ADAPTIVE} with the sobol sampler, off with the others).
 */
public record RenderDto(
        @Pattern(regexp = RenderDto.SAMPLERS, message = RenderDto.SAMPLERS_MESSAGE) String sampler,
        @Positive Integer samples,
        @PositiveOrZero Integer maxDepth,
        Long seed,
        @PositiveOrZero @DecimalMax("1") @Finite Double adaptive) {

    /** The engine's Sampler.names(), in its order (a test checks they agree). */
    public static final String SAMPLERS = "regular|random|jittered|multijittered|sobol";
    public static final String SAMPLERS_MESSAGE =
            "must be one of \"regular\", \"random\", \"jittered\", \"multijittered\", \"sobol\"";

    /** Without a threshold: the default applies. */
    public RenderDto(String sampler, Integer samples, Integer maxDepth, Long seed) {
        this(sampler, samples, maxDepth, seed, null);
    }
}
