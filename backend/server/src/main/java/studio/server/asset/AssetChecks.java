package studio.server.asset;

import java.nio.ByteBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;

import studio.engine.memory.MemoryGate;
import studio.engine.mesh.ObjReader;
import studio.engine.mesh.TooManyTrianglesException;

/**
 * What bytes must be to be kept as an asset of their declared kind: they start as that kind does
 * (a media type that lies is refused), and then an OBJ reads as a mesh (the engine's reader) within
 * the triangle limit, an image's header declares at most the pixel limit (nothing is decoded), and a
 * glTF is a well-formed container ({@link GltfContainers}).
 *
 * @param maxTriangles studio.limits.max-triangles: the most triangles a scene's meshes may have together
 * @param maxPixels    studio.assets.max-pixels
 */
record AssetChecks(int maxTriangles, long maxPixels) {

    /**
     * @param memory asked before the OBJ reader allocates
     * @throws AssetRefusedException (400) saying what is wrong
     */
    void check(AssetType declared, byte[] bytes, MemoryGate memory) {
        if (bytes.length == 0) {
            throw AssetRefusedException.invalid(declared, "the body is empty");
        }
        AssetType looks = AssetType.sniff(bytes);
        if (looks != declared) {
            throw AssetRefusedException.invalid(declared, "the bytes look like " + looks.looksLike() + ", not "
                    + declared.looksLike() + " (send them with Content-Type " + looks.mediaType() + ")");
        }
        try {
            switch (declared) {
                case OBJ -> obj(bytes, memory);
                case PNG -> pixels(ImageHeaders.png(bytes));
                case JPEG -> pixels(ImageHeaders.jpeg(bytes));
                case GLB -> GltfContainers.glb(bytes);
                case GLTF -> GltfContainers.gltf(bytes);
            }
        } catch (IllegalArgumentException e) {
            throw AssetRefusedException.invalid(declared, e.getMessage());
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
