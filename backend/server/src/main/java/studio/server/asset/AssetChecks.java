package studio.server.asset;

import java.nio.ByteBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.util.List;

import studio.engine.memory.MemoryGate;
import studio.engine.mesh.ObjReader;
import studio.engine.mesh.TooManyTrianglesException;
import studio.server.scene.gltf.GltfAssets;
import studio.server.scene.gltf.GltfReader;

/**
 * What bytes must be to be kept as an asset of their declared kind: they start as that kind does
 * (a media type that lies is refused), and then an OBJ reads as a mesh (the engine's reader) within
 * the triangle limit, an image's header declares at most the pixel limit (nothing is decoded), and a
 * glTF reads as a model that can be drawn ({@link GltfReader}), within the triangle limit, its buffers
 * and images named by id among the assets kept already. A .gltf's buffer (application/octet-stream) is
 * any bytes.
 *
 * @param maxTriangles studio.limits.max-triangles: the most triangles a scene's meshes may have together
 * @param maxPixels    studio.assets.max-pixels
 */
record AssetChecks(int maxTriangles, long maxPixels) {

    /**
     * @param memory asked before the OBJ and glTF readers allocate
     * @param kept   the assets kept already, which a .gltf may name
     * @return what a glTF model holds that is not drawn (empty for other kinds)
     * @throws AssetRefusedException (400) saying what is wrong
     */
    List<String> check(AssetType declared, byte[] bytes, MemoryGate memory, GltfAssets kept) {
        if (bytes.length == 0) {
            throw AssetRefusedException.invalid(declared, "the body is empty");
        }
        AssetType looks = AssetType.sniff(bytes);
        if (looks != declared && declared != AssetType.BIN) {
            throw AssetRefusedException.invalid(declared, "the bytes look like " + looks.looksLike() + ", not "
                    + declared.looksLike() + " (send them with Content-Type " + looks.mediaType() + ")");
        }
        try {
            switch (declared) {
                case OBJ -> obj(bytes, memory);
                case PNG -> pixels(ImageHeaders.png(bytes));
                case JPEG -> pixels(ImageHeaders.jpeg(bytes));
                case GLB, GLTF -> {
                    return gltf(bytes, memory, kept);
                }
                case BIN -> {
                    // any bytes: a glTF that names this buffer checks its bounds when it is read
                }
            }
        } catch (IllegalArgumentException e) {
            throw AssetRefusedException.invalid(declared, e.getMessage());
        }
        return List.of();
    }

    private List<String> gltf(byte[] bytes, MemoryGate memory, GltfAssets kept) {
        try {
            return GltfReader.read(bytes, kept, maxTriangles, memory).warnings();
        } catch (GltfReader.TooManyTrianglesException e) {
            throw new IllegalArgumentException("it draws " + e.triangles() + " triangles; this server's limit is "
                    + maxTriangles + " (studio.limits.max-triangles)");
        }
    }

    private void obj(byte[] bytes, MemoryGate memory) {
        String text;
        try {
            text = StandardCharsets.UTF_8.newDecoder().onMalformedInput(CodingErrorAction.REPORT)
                    .onUnmappableCharacter(CodingErrorAction.REPORT).decode(ByteBuffer.wrap(bytes)).toString();
        } catch (CharacterCodingException e) {
            throw new IllegalArgumentException("OBJ is UTF-8 text, and these bytes are not");
        }
        if (text.indexOf('\0') >= 0) {
            throw new IllegalArgumentException("OBJ is text, and these bytes hold a NUL");
        }
        try {
            ObjReader.parse(text, maxTriangles, memory);
        } catch (TooManyTrianglesException e) {
            throw new IllegalArgumentException("it has more than " + maxTriangles + " triangles (passed at OBJ line "
                    + e.line() + "); this server's limit is " + maxTriangles + " (studio.limits.max-triangles)");
        }
    }

    private void pixels(ImageHeaders.Size size) {
        if (size.pixels() > maxPixels) {
            throw new IllegalArgumentException("its header declares " + size.width() + " x " + size.height() + " = "
                    + size.pixels() + " pixels; this server's limit is " + maxPixels + " (studio.assets.max-pixels)");
        }
    }
}
