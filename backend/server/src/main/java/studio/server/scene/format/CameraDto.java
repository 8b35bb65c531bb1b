package studio.server.scene.format;

import java.util.List;

import jakarta.validation.constraints.DecimalMax;
import jakarta.validation.constraints.DecimalMin;
import jakarta.validation.constraints.NotNull;

/** A perspective camera; {@code fov} is the vertical field of view in degrees, as three.js. */
public record CameraDto(
        @Vector List<@NotNull(message = "must be a number") @DecimalMin(Coordinates.MIN) @DecimalMax(Coordinates.MAX) @Finite Double> position,
        @Vector List<@NotNull(message = "must be a number") @DecimalMin(Coordinates.MIN) @DecimalMax(Coordinates.MAX) @Finite Double> lookAt,
        @Vector @NonZeroVector List<@NotNull(message = "must be a number") @Finite Double> up,
        @DecimalMin(value = "0", inclusive = false) @DecimalMax(value = "180", inclusive = false) @Finite Double fov) {
}
