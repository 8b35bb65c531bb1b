package studio.server.scene.compiling;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;

import studio.server.scene.format.GltfFileNames;
import studio.server.scene.format.MeshFileNames;

/**
 * Where a mesh's or a glTF model's {@code file} is read from. The command line reads files beside the
 * scene file; the service reads only the meshes shipped with its example scenes (anything else is
 * sent inline as {@code obj}, or uploaded as an asset).
 */
@FunctionalInterface
public interface MeshFiles {

    /**
     * The bytes of {@code file}, a name that follows one of the format's rules.
     *
     * @throws IllegalArgumentException saying that there is no such file, or that it cannot be read
     */
    byte[] bytes(String file);

    /**
     * The OBJ text of {@code file}.
     *
     * @throws IllegalArgumentException saying what is wrong with the name, or that there is no such file
     */
    default String read(String file) {
        if (!MeshFileNames.PATTERN.matcher(file).matches()) {
            throw new IllegalArgumentException(MeshFileNames.MESSAGE);
        }
        return new String(bytes(file), StandardCharsets.UTF_8);
    }

    /**
     * The bytes of the glTF model (.glb or .gltf) {@code file}.
     *
     * @throws IllegalArgumentException saying what is wrong with the name, or that there is no such file
     */
    default byte[] gltf(String file) {
        if (!GltfFileNames.PATTERN.matcher(file).matches()) {
            throw new IllegalArgumentException(GltfFileNames.MESSAGE);
        }
        return bytes(file);
    }

    /** The meshes shipped in the jar under scenes/ (copied from scenes/ at build time). */
    static MeshFiles bundled() {
        return file -> {
            try (InputStream in = MeshFiles.class.getClassLoader().getResourceAsStream("scenes/" + file)) {
                if (in == null) {
                    throw new IllegalArgumentException("no mesh '" + file + "' ships with this server; " + instead(file)
                            + " instead");
                }
                return in.readAllBytes();
            } catch (IOException e) {
                throw new IllegalArgumentException("cannot read the mesh '" + file + "': " + e.getMessage());
            }
        };
    }

    /** Files relative to a folder, e.g. the one holding the scene file. */
    static MeshFiles in(Path folder) {
        return file -> {
            Path path = folder.resolve(file);
            try {
                return Files.readAllBytes(path);
            } catch (NoSuchFileException e) {
                throw new IllegalArgumentException("no such file: " + path);
            } catch (IOException e) {
                throw new IllegalArgumentException("cannot read " + path + ": " + e.getMessage());
            }
        };
    }

    /** No files at all: meshes must be inline, models uploaded as assets. */
    static MeshFiles none() {
        return file -> {
            throw new IllegalArgumentException("mesh files cannot be read here; " + instead(file));
        };
    }

    private static String instead(String file) {
        return file.endsWith(".obj") ? "send the OBJ text inline as \"obj\""
                : "upload it (POST /api/assets) and name its id in \"asset\"";
    }
}
