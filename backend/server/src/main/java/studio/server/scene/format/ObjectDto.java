package studio.server.scene.format;

import java.util.List;

import com.fasterxml.jackson.annotation.JsonSubTypes;
import com.fasterxml.jackson.annotation.JsonTypeInfo;

import org.hibernate.validator.constraints.CodePointLength;

import jakarta.validation.Valid;
import jakarta.validation.constraints.DecimalMax;
import jakarta.validation.constraints.DecimalMin;
import jakarta.validation.constraints.NotNull;
import jakarta.validation.constraints.Pattern;
import jakarta.validation.constraints.Positive;

/**
 * A scene object; {@code type} names its kind. Each may carry a {@code name} the user gave it in the editor;
 * the engine ignores it (it is the editor's, kept in the file so a scene reopens with its names).
 */
@JsonTypeInfo(use = JsonTypeInfo.Id.NAME, property = "type")
@JsonSubTypes({
        @JsonSubTypes.Type(value = ObjectDto.Sphere.class, name = "sphere"),
        @JsonSubTypes.Type(value = ObjectDto.Box.class, name = "box"),
        @JsonSubTypes.Type(value = ObjectDto.Plane.class, name = "plane"),
        @JsonSubTypes.Type(value = ObjectDto.Mesh.class, name = "mesh"),
        @JsonSubTypes.Type(value = ObjectDto.Gltf.class, name = "gltf")})
public sealed interface ObjectDto {

    /** The object's material; null for a glTF model, whose materials come from its file. */
    MaterialDto material();

    record Sphere(
            @Vector List<@NotNull(message = "must be a number") @DecimalMin(Coordinates.MIN) @DecimalMax(Coordinates.MAX) @Finite Double> center,
            @Positive @Finite Double radius,
            @Valid MaterialDto material,
            @CodePointLength(max = 200, message = "must be at most 200 characters") String name) implements ObjectDto {
    }

    /** A box: centre, full size along its own axes, rotation in degrees about x, y, z (order XYZ, as three.js). */
    record Box(
            @Vector List<@NotNull(message = "must be a number") @DecimalMin(Coordinates.MIN) @DecimalMax(Coordinates.MAX) @Finite Double> center,
            @Vector List<@NotNull(message = "must be a number") @Positive @Finite Double> size,
            @Vector List<@NotNull(message = "must be a number") @Finite Double> rotation,
            @Valid MaterialDto material,
            @CodePointLength(max = 200, message = "must be at most 200 characters") String name) implements ObjectDto {
    }

    /** An infinite plane through {@code point} with the given normal (need not be unit length). */
    record Plane(
            @Vector List<@NotNull(message = "must be a number") @DecimalMin(Coordinates.MIN) @DecimalMax(Coordinates.MAX) @Finite Double> point,
            @Vector @NonZeroVector List<@NotNull(message = "must be a number") @Finite Double> normal,
            @Valid MaterialDto material,
            @CodePointLength(max = 200, message = "must be at most 200 characters") String name) implements ObjectDto {
    }

    /**
     * A triangle mesh from Wavefront OBJ (positions, triangles or polygons, optional vertex normals
     * for smooth shading): exactly one of the OBJ text itself in {@code obj}, a {@code file} name (see
     * {@link MeshFileNames}; the compiler's MeshFiles say where it is read from), or the id of an
     * {@code asset} uploaded before (see {@link AssetIds}). Placed by a uniform
     * scale, then the rotation (degrees, order XYZ as three.js), then moved to {@code position}.
     */
    record Mesh(
            String obj,
            @Pattern(regexp = MeshFileNames.RULE, message = MeshFileNames.MESSAGE) String file,
            @Pattern(regexp = AssetIds.RULE, message = AssetIds.MESSAGE) String asset,
            @Vector List<@NotNull(message = "must be a number") @DecimalMin(Coordinates.MIN) @DecimalMax(Coordinates.MAX) @Finite Double> position,
            @Positive @Finite Double scale,
            @Vector List<@NotNull(message = "must be a number") @Finite Double> rotation,
            @Valid MaterialDto material,
            @CodePointLength(max = 200, message = "must be at most 200 characters") String name) implements ObjectDto {
    }

    /**
     * A glTF 2.0 model (.glb, or .gltf with its buffers and images embedded as data: URIs or named by
     * asset id): exactly one of a {@code file} name (see {@link GltfFileNames}) or the id of an
     * {@code asset} uploaded before. Its default scene is drawn with the file's node transforms and
     * materials, then placed as a mesh is: a uniform scale, then the rotation (degrees, order XYZ as
     * three.js), then moved to {@code position}.
     */
    record Gltf(
            @Pattern(regexp = GltfFileNames.RULE, message = GltfFileNames.MESSAGE) String file,
            @Pattern(regexp = AssetIds.RULE, message = AssetIds.MESSAGE) String asset,
            @Vector List<@NotNull(message = "must be a number") @DecimalMin(Coordinates.MIN) @DecimalMax(Coordinates.MAX) @Finite Double> position,
            @Positive @Finite Double scale,
            @Vector List<@NotNull(message = "must be a number") @Finite Double> rotation,
            @CodePointLength(max = 200, message = "must be at most 200 characters") String name) implements ObjectDto {

        /** None: a model's materials are its file's. */
        @Override
        public MaterialDto material() {
            return null;
        }
    }
}
