package studio.server.scene.format;

import java.util.List;

import com.fasterxml.jackson.annotation.JsonSubTypes;
import com.fasterxml.jackson.annotation.JsonTypeInfo;

import org.hibernate.validator.constraints.CodePointLength;

import jakarta.validation.constraints.DecimalMax;
import jakarta.validation.constraints.NotNull;
import jakarta.validation.constraints.Pattern;
import jakarta.validation.constraints.PositiveOrZero;

/** A light; {@code type} names its kind; an optional {@code name} is the editor's, ignored by the engine. */
@JsonTypeInfo(use = JsonTypeInfo.Id.NAME, property = "type")
@JsonSubTypes({@JsonSubTypes.Type(value = LightDto.Point.class, name = "point")})
public sealed interface LightDto {

    /** A point light; no distance fall-off unless {@code falloff} is true (then 1/distance squared). */
    record Point(
            @Vector List<@NotNull(message = "must be a number") @Finite Double> position,
            @Pattern(regexp = SceneDto.COLOR, message = SceneDto.COLOR_MESSAGE) String color,
            @PositiveOrZero @DecimalMax("1e6") @Finite Double intensity,
            Boolean falloff,
            @CodePointLength(max = 200, message = "must be at most 200 characters") String name) implements LightDto {
    }
}
