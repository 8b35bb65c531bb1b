package studio.server.scene.format;

import com.fasterxml.jackson.annotation.JsonSubTypes;
import com.fasterxml.jackson.annotation.JsonTypeInfo;

import jakarta.validation.constraints.DecimalMax;
import jakarta.validation.constraints.DecimalMin;
import jakarta.validation.constraints.Pattern;
import jakarta.validation.constraints.PositiveOrZero;

/**
 * A material; {@code type} names one of the six kinds, and each kind takes only the overrides it
 * uses (an override another kind uses is an unknown field here). Left-out values take the
 * engine's defaults ({@code studio.engine.material.MaterialDefaults}).
 */
@JsonTypeInfo(use = JsonTypeInfo.Id.NAME, property = "type")
@JsonSubTypes({
        @JsonSubTypes.Type(value = MaterialDto.Flat.class, name = "flat"),
        @JsonSubTypes.Type(value = MaterialDto.Chalk.class, name = "chalk"),
        @JsonSubTypes.Type(value = MaterialDto.Plastic.class, name = "plastic"),
        @JsonSubTypes.Type(value = MaterialDto.Metal.class, name = "metal"),
        @JsonSubTypes.Type(value = MaterialDto.Mirror.class, name = "mirror"),
        @JsonSubTypes.Type(value = MaterialDto.Glass.class, name = "glass")})
public sealed interface MaterialDto {

    String color();

    /** Its colour, unlit. */
    record Flat(@Pattern(regexp = SceneDto.COLOR, message = SceneDto.COLOR_MESSAGE) String color)
            implements MaterialDto {
    }

    /** Diffuse only. */
    record Chalk(
            @Pattern(regexp = SceneDto.COLOR, message = SceneDto.COLOR_MESSAGE) String color,
            @PositiveOrZero @DecimalMax("1") @Finite Double diffuse) implements MaterialDto {
    }

    /** Diffuse plus a white highlight. */
    record Plastic(
            @Pattern(regexp = SceneDto.COLOR, message = SceneDto.COLOR_MESSAGE) String color,
            @PositiveOrZero @DecimalMax("1") @Finite Double diffuse,
            @PositiveOrZero @DecimalMax("1") @Finite Double specular,
            @DecimalMin("1") @DecimalMax("10000") @Finite Double shininess) implements MaterialDto {
    }

    /** A highlight tinted by its colour and a tinted reflection. */
    record Metal(
            @Pattern(regexp = SceneDto.COLOR, message = SceneDto.COLOR_MESSAGE) String color,
            @PositiveOrZero @DecimalMax("1") @Finite Double diffuse,
            @PositiveOrZero @DecimalMax("1") @Finite Double specular,
            @DecimalMin("1") @DecimalMax("10000") @Finite Double shininess,
            @PositiveOrZero @DecimalMax("1") @Finite Double reflectivity) implements MaterialDto {
    }

    /** Perfect reflection, tinted by its colour. */
    record Mirror(
            @Pattern(regexp = SceneDto.COLOR, message = SceneDto.COLOR_MESSAGE) String color,
            @PositiveOrZero @DecimalMax("1") @Finite Double reflectivity) implements MaterialDto {
    }

    /** Refraction with an index, Fresnel reflection; its colour tints the light passing through. */
    record Glass(
            @Pattern(regexp = SceneDto.COLOR, message = SceneDto.COLOR_MESSAGE) String color,
            @DecimalMin("1") @DecimalMax("4") @Finite Double ior,
            @PositiveOrZero @DecimalMax("1") @Finite Double specular,
            @DecimalMin("1") @DecimalMax("10000") @Finite Double shininess) implements MaterialDto {
    }
}
