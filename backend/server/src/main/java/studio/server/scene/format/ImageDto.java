package studio.server.scene.format;

import jakarta.validation.constraints.DecimalMax;
import jakarta.validation.constraints.Pattern;
import jakarta.validation.constraints.Positive;
import jakarta.validation.constraints.PositiveOrZero;

/** The output image: size in pixels, file format ("jpg" or "png") and JPEG quality in [0, 1]. */
public record ImageDto(
        @Positive Integer width,
        @Positive Integer height,
        @Pattern(regexp = "jpg|png", message = "must be \"jpg\" or \"png\"") String format,
        @PositiveOrZero @DecimalMax("1") @Finite Double quality) {
}
