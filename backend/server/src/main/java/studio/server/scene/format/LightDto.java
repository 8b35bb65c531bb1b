package studio.server.scene.format;

import java.util.List;

import com.fasterxml.jackson.annotation.JsonSubTypes;
import com.fasterxml.jackson.annotation.JsonTypeInfo;

import org.hibernate.validator.constraints.CodePointLength;

import jakarta.validation.constraints.DecimalMax;
import jakarta.validation.constraints.DecimalMin;
import jakarta.validation.constraints.NotNull;
import jakarta.validation.constraints.Pattern;
import jakarta.validation.constraints.Positive;
import jakarta.validation.constraints.PositiveOrZero;

/** A light; {@code type} names its kind; an optional {@code name} is the editor's, ignored by the engine. */
@JsonTypeInfo(use = JsonTypeInfo.Id.NAME, property = "type")
@JsonSubTypes({@JsonSubTypes.Type(value = LightDto.Point.class, name = "point"),
        @JsonSubTypes.Type(value = LightDto.Area.class, name = "area")})
public sealed interface LightDto {

    /**
     * A point light; no distance fall-off unless {@code falloff} is true (then 1/distance squared).
     * A {@code radius} above 0 (metres) makes it a sphere of light, with soft shadows.
     */
    record Point(
            @Vector List<@NotNull(message = "must be a number") @DecimalMin(Coordinates.MIN) @DecimalMax(Coordinates.MAX) @Finite Double> position,
            @Pattern(regexp = SceneDto.COLOR, message = SceneDto.COLOR_MESSAGE) String color,
            @PositiveOrZero @DecimalMax("1e6") @Finite Double intensity,
            Boolean falloff,
            @PositiveOrZero @DecimalMax("1e6") @Finite Double radius,
            @CodePointLength(max = 200, message = "must be at most 200 characters") String name) implements LightDto {
    }

    /**
     * A rectangle of light, {@code size} = [width, height] metres, centred at {@code position} and
     * facing {@code lookAt} (as three.js's RectAreaLight); it emits from its front only unless
     * {@code twoSided}. {@code intensity} and {@code falloff} as a point light's: a small one lights
     * a point on its axis as a point light would, and less by the cosine away from its axis.
     */
    record Area(
            @Vector List<@NotNull(message = "must be a number") @DecimalMin(Coordinates.MIN) @DecimalMax(Coordinates.MAX) @Finite Double> position,
            @Pair List<@NotNull(message = "must be a number") @Positive @DecimalMax("1e6") @Finite Double> size,
            @Vector List<@NotNull(message = "must be a number") @DecimalMin(Coordinates.MIN) @DecimalMax(Coordinates.MAX) @Finite Double> lookAt,
            @Pattern(regexp = SceneDto.COLOR, message = SceneDto.COLOR_MESSAGE) String color,
            @PositiveOrZero @DecimalMax("1e6") @Finite Double intensity,
            Boolean falloff,
            Boolean twoSided,
            @CodePointLength(max = 200, message = "must be at most 200 characters") String name) implements LightDto {
    }
}
