package studio.server.scene;

import jakarta.validation.constraints.Pattern;
import jakarta.validation.constraints.Positive;
import jakarta.validation.constraints.PositiveOrZero;

/** How to sample: sampler name, samples per pixel, recursion depth and the noise seed. */
public record RenderDto(
        @Pattern(regexp = "regular|jittered", message = "must be \"regular\" or \"jittered\"") String sampler,
        @Positive Integer samples,
        @PositiveOrZero Integer maxDepth,
        Long seed) {
}
