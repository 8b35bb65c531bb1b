package studio.server.preview;

import java.util.Arrays;

import tools.jackson.core.JacksonException;
import tools.jackson.core.JsonParser;
import tools.jackson.core.JsonToken;
import tools.jackson.core.ObjectReadContext;
import tools.jackson.core.json.JsonFactory;

/**
 * Where each element of a scene's top-level {@code objects} array lies in the scene's JSON bytes,
 * found by one streaming pass that builds nothing.
 */
final class SceneObjectsInJson {

    private static final JsonFactory JSON = new JsonFactory();

    private SceneObjectsInJson() {
    }

    /**
     * For each element of the scene's {@code objects} array, its first byte and the byte after its
     * last, two ints an element ({@code [start0, end0, start1, end1, ...]}); null unless the scene is
     * a JSON object with exactly one {@code objects} member, an array of one or more JSON objects,
     * and the rest of it well-formed as far as a streaming pass can tell.
     */
    static int[] ranges(byte[] scene) {
        int[] found = null;
        try (JsonParser parser = JSON.createParser(ObjectReadContext.empty(), scene)) {
            if (parser.nextToken() != JsonToken.START_OBJECT) {
                return null;
            }
            while (parser.nextToken() == JsonToken.PROPERTY_NAME) {
                boolean objects = parser.currentName().equals("objects");
                JsonToken value = parser.nextToken();
                if (!objects) {
                    parser.skipChildren();
                } else if (found != null || value != JsonToken.START_ARRAY) {
                    return null;
                } else {
                    found = elements(parser, scene);
                    if (found == null) {
                        return null;
                    }
                }
            }
            if (parser.currentToken() != JsonToken.END_OBJECT || parser.nextToken() != null) {
                return null;
            }
        } catch (JacksonException e) {
            return null;
        }
        return found != null && found.length > 0 ? found : null;
    }

    /** The array's elements from just after its '[', each a JSON object; null if one is not. */
    private static int[] elements(JsonParser parser, byte[] scene) {
        int[] ranges = new int[16];
        int count = 0;
        JsonToken token;
        while ((token = parser.nextToken()) != JsonToken.END_ARRAY) {
            if (token != JsonToken.START_OBJECT) {
                return null;
            }
            int start = (int) parser.currentTokenLocation().getByteOffset();
            parser.skipChildren();
            int end = (int) parser.currentLocation().getByteOffset();
            if (start < 0 || end > scene.length || scene[start] != '{' || scene[end - 1] != '}') {
                return null;
            }
            if (count + 2 > ranges.length) {
                ranges = Arrays.copyOf(ranges, 2 * ranges.length);
            }
            ranges[count++] = start;
            ranges[count++] = end;
        }
        return Arrays.copyOf(ranges, count);
    }
}
