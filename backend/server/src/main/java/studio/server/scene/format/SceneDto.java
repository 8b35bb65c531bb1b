package studio.server.scene.format;

import java.util.List;

import org.hibernate.validator.constraints.CodePointLength;

import jakarta.validation.Valid;
import jakarta.validation.constraints.DecimalMax;
import jakarta.validation.constraints.Max;
import jakarta.validation.constraints.Min;
import jakarta.validation.constraints.NotNull;
import jakarta.validation.constraints.Pattern;
import jakarta.validation.constraints.PositiveOrZero;

/**
 * A scene file, as the editor saves it, the API takes it and the CLI reads it. Every field but
 * {@code objects} may be left out and then takes its default ({@link SceneDefaults}).
 */
public record SceneDto(
        @Min(value = 1, message = "must be 1 (the only scene format version there is)")
        @Max(value = SceneDto.FORMAT_VERSION, message = "is newer than this server understands (it reads version 1)")
        Integer version,
        @CodePointLength(max = 200, message = "must be at most 200 characters") String name,
        @Valid ImageDto image,
        @Valid CameraDto camera,
        @Pattern(regexp = SceneDto.COLOR, message = SceneDto.COLOR_MESSAGE) String background,
        @PositiveOrZero @DecimalMax("1") @Finite Double ambient,
        @Valid RenderDto render,
        List<@NotNull(message = "must be a light") @Valid LightDto> lights,
        @NotNull(message = "is required (a list of objects, possibly empty)")
        List<@NotNull(message = "must be an object") @Valid ObjectDto> objects) {

    public static final int FORMAT_VERSION = 1;
    static final String COLOR = "#[0-9a-fA-F]{6}";
    static final String COLOR_MESSAGE = "must be a colour of the form #rrggbb";
}
