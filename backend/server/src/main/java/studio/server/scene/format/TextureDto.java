package studio.server.scene.format;

import java.util.List;

import com.fasterxml.jackson.annotation.JsonSubTypes;
import com.fasterxml.jackson.annotation.JsonTypeInfo;

import jakarta.validation.constraints.NotNull;
import jakarta.validation.constraints.Pattern;
import jakarta.validation.constraints.Positive;

/**
 * A material's texture, which its colour multiplies (as glTF's baseColorFactor times
 * baseColorTexture); {@code type} names its kind. How many colours and scale factors there are is
 * checked where the texture is mapped (TextureMapping), with the field's path.
 */
@JsonTypeInfo(use = JsonTypeInfo.Id.NAME, property = "type")
@JsonSubTypes({
        @JsonSubTypes.Type(value = TextureDto.Checker.class, name = "checker"),
        @JsonSubTypes.Type(value = TextureDto.Image.class, name = "image")})
public sealed interface TextureDto {

    /** Squares of two colours ({@code colors}, exactly two), {@code size} metres a side (default 1). */
    record Checker(
            List<@NotNull(message = "must be a colour") @Pattern(regexp = SceneDto.COLOR,
                    message = SceneDto.COLOR_MESSAGE) String> colors,
            @Positive @Finite Double size) implements TextureDto {
    }

    /**
     * A PNG or JPEG image: exactly one of the id of an {@code asset} uploaded before, or a {@code file}
     * beside the scene (the command line); repeated {@code scale} = [su, sv] times per unit of the
     * surface's texture coordinates (default [1, 1]).
     */
    record Image(
            @Pattern(regexp = AssetIds.RULE, message = AssetIds.MESSAGE) String asset,
            @Pattern(regexp = ImageFileNames.RULE, message = ImageFileNames.MESSAGE) String file,
            List<@NotNull(message = "must be a number") @Positive @Finite Double> scale) implements TextureDto {
    }
}
