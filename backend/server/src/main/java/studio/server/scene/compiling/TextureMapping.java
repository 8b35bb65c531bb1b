package studio.server.scene.compiling;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.util.Iterator;
import java.util.List;

import javax.imageio.ImageIO;
import javax.imageio.ImageReader;
import javax.imageio.stream.ImageInputStream;

import studio.engine.memory.MemoryGate;
import studio.engine.texture.CheckerTexture;
import studio.engine.texture.ImageTexture;
import studio.engine.texture.MipMap;
import studio.engine.texture.Texture;
import studio.server.scene.format.TextureDto;

/**
 * A material's texture onto the engine's: a checker's two colours, or an image (its {@code asset}
 * from the server's store, or its {@code file} beside the scene, as {@link MeshMapping} reads a mesh's),
 * decoded from sRGB into a mip-map once and kept in the {@link TextureCache}. Problems name the field.
 */
final class TextureMapping {

    private final TextureCache cache;
    private final MeshFiles files;
    private final ImageAssets assets;
    private final MemoryGate memory;
    private final MappingProblems problems;

    TextureMapping(TextureCache cache, MeshFiles files, ImageAssets assets, MemoryGate memory, MappingProblems problems) {
        this.cache = cache;
        this.files = files;
        this.assets = assets;
        this.memory = memory;
        this.problems = problems;
    }

    /** The texture at {@code path} (a material's {@code texture}), null if there is none, or a problem. */
    Texture of(TextureDto dto, String path) {
        if (dto instanceof TextureDto.Checker c) {
            return checker(c, path);
        }
        if (dto instanceof TextureDto.Image i) {
            return image(i, path);
        }
        return null;
    }

    private Texture checker(TextureDto.Checker c, String path) {
        List<String> colors = c.colors();
        if (colors == null || colors.size() != 2) {
            problems.add(path + ".colors", "must be exactly two colours [\"#rrggbb\", \"#rrggbb\"]");
            return null;
        }
        return problems.attempt(path, () -> new CheckerTexture(Colors.linear(colors.get(0)), Colors.linear(colors.get(1)),
                c.size() != null ? c.size() : 1));
    }

    private Texture image(TextureDto.Image dto, String path) {
        if ((dto.asset() != null) == (dto.file() != null)) {
            problems.add(path, "an image texture needs exactly one of an \"asset\" id and a \"file\" name");
            return null;
        }
        List<Double> scale = dto.scale() != null ? dto.scale() : List.of(1.0, 1.0);
        if (scale.size() != 2) {
            problems.add(path + ".scale", "must be two numbers [su, sv]");
            return null;
        }
        MipMap image = dto.asset() != null ? fromAsset(dto.asset(), path + ".asset") : fromFile(dto.file(), path + ".file");
        return image == null ? null : problems.attempt(path, () -> new ImageTexture(image, scale.get(0), scale.get(1)));
    }

    private MipMap fromAsset(String id, String field) {
        String key = cache.keyOfAsset(id);
        MipMap kept = cache.get(key);
        if (kept != null) {
            return kept;
        }
        byte[] bytes = problems.attempt(field, () -> assets.image(id));
        if (bytes == null) {
            if (!problems.has(field)) {
                problems.add(field, "this server has no asset " + id + "; upload it (POST /api/assets) and send the "
                        + "scene again");
            }
            return null;
        }
        MipMap image = problems.attempt(field, () -> decode(bytes, memory));
        if (image != null) {
            cache.keep(key, image);
        }
        return image;
    }

    private MipMap fromFile(String file, String field) {
        byte[] bytes = problems.attempt(field, () -> files.image(file));
        return bytes == null ? null : problems.attempt(field, () -> decode(bytes, memory));
    }

    /**
     * PNG or JPEG bytes, sRGB, into a linear mip-map, the memory it takes asked of {@code memory} first
     * (also for images inside other assets, such as a glb's).
     *
     * @throws IllegalArgumentException if the bytes are not an image javax.imageio reads
     */
    static MipMap decode(byte[] bytes, MemoryGate memory) {
        // the size from the header first: the memory is asked before a declared 100,000 x 100,000
        // image (inside a glb, say, which no upload check saw) is decoded
        int w, h;
        try (ImageInputStream in = ImageIO.createImageInputStream(new ByteArrayInputStream(bytes))) {
            Iterator<ImageReader> readers = in == null ? null : ImageIO.getImageReaders(in);
            if (readers == null || !readers.hasNext()) {
                throw new IllegalArgumentException("is not a PNG or JPEG image");
            }
            ImageReader reader = readers.next();
            try {
                reader.setInput(in, true, true);
                w = reader.getWidth(0);
                h = reader.getHeight(0);
            } finally {
                reader.dispose();
            }
        } catch (IOException | RuntimeException e) {
            if (e instanceof IllegalArgumentException bad) {
                throw bad;
            }
            throw new IllegalArgumentException("is not a PNG or JPEG image this server can read: " + e.getMessage());
        }
        memory.reserve(2 * MemoryGate.ints((long) w * h)); // the decoded image and its pixels as ints
        BufferedImage image;
        try {
            image = ImageIO.read(new ByteArrayInputStream(bytes));
        } catch (IOException | RuntimeException e) {
            throw new IllegalArgumentException("is not a PNG or JPEG image this server can read: " + e.getMessage());
        }
        if (image == null || image.getWidth() != w || image.getHeight() != h) {
            throw new IllegalArgumentException("is not a PNG or JPEG image");
        }
        return MipMap.fromSrgb(w, h, image.getRGB(0, 0, w, h, null, 0, w), memory);
    }
}
