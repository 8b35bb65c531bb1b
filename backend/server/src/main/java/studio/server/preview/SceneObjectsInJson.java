package studio.server.preview;

import java.util.Arrays;

import tools.jackson.core.JacksonException;
import tools.jackson.core.JsonParser;
import tools.jackson.core.JsonToken;

/**
 * Where each element of a scene's top-level {@code objects} array lies in the scene's JSON bytes,
 * found by one streaming pass that builds nothing.
 *
 * <p>Byte ranges, not Jackson trees compared: 3.5 ms a 10,000-sphere drag step against 14-15 (PreviewReadingBench).
 */
final class SceneObjectsInJson {

    private SceneObjectsInJson() {
    }

    /** Ints a scene's object takes in {@link #scan}'s answer. */
    static final int PER_OBJECT = 4;

    /**
     * Where the elements of the {@code objects} array of a scene that a parser over {@code json} is
     * reading lie, the parser at the scene's {@code START_OBJECT}, which begins at byte
     * {@code base}; the ranges count from there. For each element, {@value #PER_OBJECT} ints: its
     * first byte, the byte after its last, and the same for the value of its {@code obj} member if
     * that is a string (an inline mesh's OBJ text, quotes included; -1, -1 if there is none); null
     * unless the scene has exactly one {@code objects} member, an array of one or more JSON objects.
     * A string's characters are skipped, not decoded. Reads the scene to its end, as
     * {@code skipChildren} would, whatever it finds.
     *
     * @throws JacksonException if the JSON is malformed, as skipping it would
     */
    static int[] scan(JsonParser parser, byte[] json, int base) {
        int[] found = null;
        boolean usable = true;
        while (parser.nextToken() == JsonToken.PROPERTY_NAME) {
            boolean objects = parser.currentName().equals("objects");
            JsonToken value = parser.nextToken();
            if (objects && found == null && usable && value == JsonToken.START_ARRAY) {
                found = elements(parser, json);
                usable = found != null;
            } else {
                usable &= !objects;
                parser.skipChildren();
            }
        }
        if (!usable || found == null || found.length == 0) {
            return null;
        }
        for (int i = 0; i < found.length; i++) {
            if (found[i] >= 0) {
                found[i] -= base;
            }
        }
        return found;
    }

    /** The array's elements from just after its '[', each a JSON object; null if one is not (read to the array's end all the same). */
    private static int[] elements(JsonParser parser, byte[] scene) {
        int[] ranges = new int[4 * PER_OBJECT];
        int count = 0;
        boolean usable = true;
        JsonToken token;
        while ((token = parser.nextToken()) != JsonToken.END_ARRAY) {
            if (token != JsonToken.START_OBJECT || !usable) {
                usable = false;
                parser.skipChildren();
                continue;
            }
            int start = (int) parser.currentTokenLocation().getByteOffset();
            int objStart = -1, objEnd = -1;
            boolean objPending = false;
            while (true) {
                JsonToken member = parser.nextToken();
                if (objPending) {
                    // the text's closing quote: the last one before the next member's name or the '}'
                    objEnd = closingQuoteBefore(scene, (int) parser.currentTokenLocation().getByteOffset());
                    objStart = objEnd < 0 ? -1 : objStart;
                    objPending = false;
                }
                if (member != JsonToken.PROPERTY_NAME) {
                    break;
                }
                boolean obj = parser.currentName().equals("obj");
                if (parser.nextToken() == JsonToken.VALUE_STRING && obj && objStart < 0) {
                    objStart = (int) parser.currentTokenLocation().getByteOffset();
                    objPending = true;
                } else {
                    parser.skipChildren();
                }
            }
            int end = (int) parser.currentLocation().getByteOffset();
            if (start < 0 || end > scene.length || scene[start] != '{' || scene[end - 1] != '}'
                    || (objStart >= 0 && scene[objStart] != '"')) {
                usable = false;
                continue;
            }
            if (count + PER_OBJECT > ranges.length) {
                ranges = Arrays.copyOf(ranges, 2 * ranges.length);
            }
            ranges[count++] = start;
            ranges[count++] = end;
            ranges[count++] = objStart;
            ranges[count++] = objEnd;
        }
        return usable ? Arrays.copyOf(ranges, count) : null;
    }

    /** The byte after the '"' that ends a string value followed, after whitespace and a comma, by byte {@code next}; -1 if there is none. */
    private static int closingQuoteBefore(byte[] json, int next) {
        int i = next - 1;
        while (i >= 0 && (json[i] == ' ' || json[i] == '\t' || json[i] == '\n' || json[i] == '\r' || json[i] == ',')) {
            i--;
        }
        return i >= 0 && json[i] == '"' ? i + 1 : -1;
    }
}
