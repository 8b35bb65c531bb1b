package studio.server.scene.gltf;

import java.util.Set;

import tools.jackson.databind.JsonNode;

/**
 * A glTF's textures' images as bytes: from a base64 {@code data:} URI, an asset named by id, or a
 * buffer view (with its {@code mimeType}). Only PNG and JPEG are drawn (their first bytes decide); any
 * other image, or a texture whose image comes from an extension, is listed as a warning and left out.
 * Images are not decoded here.
 */
final class GltfImages {

    private final JsonNode textures;
    private final JsonNode images;
    private final GltfBuffers buffers;
    private final GltfAssets assets;
    private final Set<String> warnings;

    GltfImages(JsonNode root, GltfBuffers buffers, GltfAssets assets, Set<String> warnings) {
        this.textures = GltfJson.array(root, "textures", "");
        this.images = GltfJson.array(root, "images", "");
        this.buffers = buffers;
        this.assets = assets;
        this.warnings = warnings;
    }

    int textureCount() {
        return textures.size();
    }

    /** Texture {@code t}'s image, or null (and a warning) if it is not one that is drawn. */
    GltfTexture texture(int t) {
        String path = "textures[" + t + "]";
        JsonNode texture = GltfJson.element(textures, t, "textures");
        int source = GltfJson.optionalIndex(texture, "source", images.size(), "images", path);
        if (source < 0) {
            warnings.add(path + ": it has no PNG or JPEG source (only " + texture.path("extensions").propertyNames()
                    + "), so it is not drawn");
            return null;
        }
        String imagePath = "images[" + source + "]";
        JsonNode image = GltfJson.element(images, source, "images");
        String uri = GltfJson.string(image, "uri", imagePath);
        byte[] bytes;
        if (uri != null) {
            bytes = GltfBuffers.uriBytes(uri, imagePath + ".uri", assets);
        } else {
            int view = GltfJson.index(image, "bufferView", buffers.viewCount(), "bufferViews", imagePath);
            Slice s = buffers.view(view);
            bytes = new byte[s.length()];
            System.arraycopy(s.bytes(), s.offset(), bytes, 0, s.length());
        }
        String mediaType = mediaType(bytes);
        if (mediaType == null) {
            warnings.add(imagePath + ": it is neither PNG nor JPEG, so its texture is not drawn");
            return null;
        }
        return new GltfTexture(bytes, mediaType, imagePath);
    }

    private static String mediaType(byte[] b) {
        if (b.length >= 8 && (b[0] & 0xff) == 0x89 && b[1] == 'P' && b[2] == 'N' && b[3] == 'G') {
            return "image/png";
        }
        if (b.length >= 3 && (b[0] & 0xff) == 0xff && (b[1] & 0xff) == 0xd8 && (b[2] & 0xff) == 0xff) {
            return "image/jpeg";
        }
        return null;
    }
}
