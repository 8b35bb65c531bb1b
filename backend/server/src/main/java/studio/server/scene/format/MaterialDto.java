package studio.server.scene.format;

import com.fasterxml.jackson.annotation.JsonSubTypes;
import com.fasterxml.jackson.annotation.JsonTypeInfo;

import jakarta.validation.Valid;
import jakarta.validation.constraints.DecimalMax;
import jakarta.validation.constraints.DecimalMin;
import jakarta.validation.constraints.Pattern;
import jakarta.validation.constraints.PositiveOrZero;

/**
 * A material; {@code type} names one of the six kinds, and each kind takes only the overrides it
 * uses (an override another kind uses is an unknown field here). Left-out values take the
 * engine's defaults ({@code studio.engine.material.MaterialDefaults}). Any kind takes an optional
 * {@code texture} ({@link TextureDto}) that its colour multiplies.
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

    /** What the colour is multiplied by over the surface, or null: the colour alone. */
    TextureDto texture();

    /** Its colour, unlit. */
    record Flat(@Pattern(regexp = SceneDto.COLOR, message = SceneDto.COLOR_MESSAGE) String color,
            @Valid TextureDto texture) implements MaterialDto {

        /** Untextured. */
        public Flat(String color) {
            this(color, null);
        }
    }

    /** Diffuse only. */
    record Chalk(
            @Pattern(regexp = SceneDto.COLOR, message = SceneDto.COLOR_MESSAGE) String color,
            @PositiveOrZero @DecimalMax("1") @Finite Double diffuse,
            @Valid TextureDto texture) implements MaterialDto {

        /** Untextured. */
        public Chalk(String color, Double diffuse) {
            this(color, diffuse, null);
        }
    }

    /** Diffuse plus a white highlight. */
    record Plastic(
            @Pattern(regexp = SceneDto.COLOR, message = SceneDto.COLOR_MESSAGE) String color,
            @PositiveOrZero @DecimalMax("1") @Finite Double diffuse,
            @PositiveOrZero @DecimalMax("1") @Finite Double specular,
            @DecimalMin("1") @DecimalMax("10000") @Finite Double shininess,
            @Valid TextureDto texture) implements MaterialDto {

        /** Untextured. */
        public Plastic(String color, Double diffuse, Double specular, Double shininess) {
            this(color, diffuse, specular, shininess, null);
        }
    }

    /** A highlight tinted by its colour and a tinted reflection. */
    record Metal(
            @Pattern(regexp = SceneDto.COLOR, message = SceneDto.COLOR_MESSAGE) String color,
            @PositiveOrZero @DecimalMax("1") @Finite Double diffuse,
            @PositiveOrZero @DecimalMax("1") @Finite Double specular,
            @DecimalMin("1") @DecimalMax("10000") @Finite Double shininess,
            @PositiveOrZero @DecimalMax("1") @Finite Double reflectivity,
            @Valid TextureDto texture) implements MaterialDto {

        /** Untextured. */
        public Metal(String color, Double diffuse, Double specular, Double shininess, Double reflectivity) {
            this(color, diffuse, specular, shininess, reflectivity, null);
        }
    }

    /** Perfect reflection, tinted by its colour. */
    record Mirror(
            @Pattern(regexp = SceneDto.COLOR, message = SceneDto.COLOR_MESSAGE) String color,
            @PositiveOrZero @DecimalMax("1") @Finite Double reflectivity,
            @Valid TextureDto texture) implements MaterialDto {

        /** Untextured. */
        public Mirror(String color, Double reflectivity) {
            this(color, reflectivity, null);
        }
    }

    /** Refraction with an index, Fresnel reflection; its colour tints the light passing through. */
    record Glass(
            @Pattern(regexp = SceneDto.COLOR, message = SceneDto.COLOR_MESSAGE) String color,
            @DecimalMin("1") @DecimalMax("4") @Finite Double ior,
            @PositiveOrZero @DecimalMax("1") @Finite Double specular,
            @DecimalMin("1") @DecimalMax("10000") @Finite Double shininess,
            @Valid TextureDto texture) implements MaterialDto {

        /** Untextured. */
        public Glass(String color, Double ior, Double specular, Double shininess) {
            this(color, ior, specular, shininess, null);
        }
    }
}
