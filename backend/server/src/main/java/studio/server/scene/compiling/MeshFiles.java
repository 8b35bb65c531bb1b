package studio.server.scene.compiling;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;

import studio.server.scene.format.GltfFileNames;
import studio.server.scene.format.ImageFileNames;
import studio.server.scene.format.MeshFileNames;

/**
 * Where a mesh's {@code file} is read from, a glTF model's ({@link #gltf}) and an image texture's
 * ({@link #image}). The command line reads files beside the scene file; the
 * service reads only the meshes shipped with its example scenes (anything else is sent inline as
 * {@code obj}, which is how a mesh is uploaded).
 */
@FunctionalInterface
public interface MeshFiles {

    /**
     * The OBJ text of {@code file}.
     *
     * @throws IllegalArgumentException saying what is wrong with the name, or that there is no such file
     */
    String read(String file);

    /**
     * The bytes of the glTF model (.glb or .gltf) {@code file}; only files beside a scene (the command
     * line) can be: the service takes models as assets.
     *
     * @throws IllegalArgumentException saying what is wrong with the name, or that there is no such file
     */
    default byte[] gltf(String file) {
        throw new IllegalArgumentException("glTF files cannot be read here; upload the model (POST /api/assets) "
                + "and name it by its id in \"asset\"");
    }

    /**
     * The bytes of the image {@code file} (a texture's); only files beside a scene (the command line)
     * can be: the service takes images as assets.
     *
     * @throws IllegalArgumentException saying what is wrong with the name, or that there is no such file
     */
    default byte[] image(String file) {
        throw new IllegalArgumentException("image files cannot be read here; upload the image (POST /api/assets) "
                + "and name it by its id in \"asset\"");
    }

    /** The meshes shipped in the jar under scenes/ (copied from scenes/ at build time). */
    static MeshFiles bundled() {
        return onClasspath("scenes/");
    }

    /** Meshes in the jar under {@code folder} (ending in a slash), e.g. the start-up warm-up's {@code training/}. */
    static MeshFiles onClasspath(String folder) {
        return file -> {
            requireName(file);
            try (InputStream in = MeshFiles.class.getClassLoader().getResourceAsStream(folder + file)) {
                if (in == null) {
                    throw new IllegalArgumentException("no mesh '" + file + "' ships with this server; send the "
                            + "OBJ text inline as \"obj\" instead");
                }
                return new String(in.readAllBytes(), StandardCharsets.UTF_8);
            } catch (IOException e) {
                throw new IllegalArgumentException("cannot read the mesh '" + file + "': " + e.getMessage());
            }
        };
    }

    /** Files relative to a folder, e.g. the one holding the scene file: meshes, glTF models and images. */
    static MeshFiles in(Path folder) {
        return new MeshFiles() {
            @Override
            public String read(String file) {
                requireName(file);
                return new String(bytes(folder.resolve(file)), StandardCharsets.UTF_8);
            }

            @Override
            public byte[] gltf(String file) {
                if (!GltfFileNames.PATTERN.matcher(file).matches()) {
                    throw new IllegalArgumentException(GltfFileNames.MESSAGE);
                }
                return bytes(folder.resolve(file));
            }

            @Override
            public byte[] image(String file) {
                if (!ImageFileNames.PATTERN.matcher(file).matches()) {
                    throw new IllegalArgumentException(ImageFileNames.MESSAGE);
                }
                return bytes(folder.resolve(file));
            }
        };
    }

    private static byte[] bytes(Path path) {
        try {
            return Files.readAllBytes(path);
        } catch (NoSuchFileException e) {
            throw new IllegalArgumentException("no such file: " + path);
        } catch (IOException e) {
            throw new IllegalArgumentException("cannot read " + path + ": " + e.getMessage());
        }
    }

    /** No files at all: meshes must be inline. */
    static MeshFiles none() {
        return file -> {
            throw new IllegalArgumentException("mesh files cannot be read here; send the OBJ text inline as \"obj\"");
        };
    }

    private static void requireName(String file) {
        if (!MeshFileNames.PATTERN.matcher(file).matches()) {
            throw new IllegalArgumentException(MeshFileNames.MESSAGE);
        }
    }
}
