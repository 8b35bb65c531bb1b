package studio.engine.mesh;

import java.io.IOException;
import java.io.Reader;
import java.io.StringReader;
import java.io.UncheckedIOException;
import java.util.Arrays;

import studio.engine.memory.MemoryGate;

/**
 * Reads Wavefront OBJ text into an object-space {@link MeshData}. Understood: {@code v x y z [w]}
 * (w and any further values ignored), {@code vn x y z}, {@code f} with corners {@code i},
 * {@code i/j}, {@code i//k} or {@code i/j/k}, negative (relative) indices, and polygons, which are
 * fanned into triangles, and texture coordinates ({@code vt u [v]}), kept if every face corner
 * names one (a position used with several UVs becomes several vertices); {@code o}, {@code g},
 * {@code s}, {@code usemtl}, {@code mtllib}, comments and every other statement are ignored.
 *
 * <p>Vertex normals are kept only if every face corner names one; a position used with several
 * normals becomes several vertices. Problems (a non-finite or unparsable number, an index of 0 or
 * out of range, a face with fewer than 3 corners, a zero normal) throw {@link ObjFormatException}
 * naming the line. Numbers are decimal, as OBJ writers write them: no hexadecimal floats, no
 * {@code f} or {@code d} suffixes (which {@link Double#parseDouble} would take).
 *
 * <p>A reader may be given a limit on triangles and a {@link MemoryGate}: it stops with
 * {@link TooManyTrianglesException} as soon as a face passes the limit, and asks the gate before
 * it allocates or grows any array, so neither a long text nor one polygon of millions of corners
 * can take more memory than it was granted.
 *
 * <p>Hand-rolled for speed: the text is read in chunks into one char buffer and each line is
 * tokenised in place, without regular expressions or a String per line or token. Numbers of up
 * to 19 significant digits are converted exactly by {@link DecimalToDouble} (Clinger's fast path
 * or Eisel-Lemire); longer ones, and the rare cases it declines, go to {@link Double#parseDouble}.
 * Every value is the correctly rounded one. Measured against {@link Double#parseDouble} for every
 * number (a 50,000-triangle torus with normals, 3.3 MB of OBJ, thread CPU time, alternated): warm,
 * best of 40 parses, 9.7-9.8 ms against 13.6-14.1 ms, so it is kept for the server, which reads
 * each new mesh warm; in a fresh JVM's first parse (the command line) the two were within the noise
 * (84-123 ms either way), since neither is compiled yet.
 */
public final class ObjReader {

    private final Reader in;
    private final int maxTriangles;
    private final MemoryGate memory;
    /** Buffered text; lines are parsed in place, so only the current chunk is held. */
    private char[] text;
    private int length;
    private boolean endOfInput;
    private int pos, lineEnd, line;
    private int tokenStart, tokenEnd;

    private double[] positions;
    private int positionCount;
    private double[] normals;
    private int normalCount;
    /** Per triangle corner: position index and normal index (-1: none). */
    private int[] cornerPositions;
    private int[] cornerNormals;
    private int cornerCount;
    private boolean everyCornerHasNormal = true;
    /** Texture coordinates (u, v per vt) and each corner's index into them (-1: none): null until the first vt. */
    private double[] uvs;
    private int uvCount;
    private int[] cornerUvs;
    private boolean everyCornerHasUv = true;
    /** The current face's corners. */
    private int[] facePositions;
    private int[] faceNormals;
    private int[] faceUvs;

    /**
     * @param length the text's length if known, else -1: a short text gets small buffers (a scene
     *               may hold thousands of small meshes), a long or unknown one 64 Ki chars and room
     *               for 1,024 vertices and triangles, which then double as needed
     */
    private ObjReader(Reader in, long length, int maxTriangles, MemoryGate memory) {
        if (maxTriangles < 0) {
            throw new IllegalArgumentException("the triangle limit must not be negative: " + maxTriangles);
        }
        this.in = in;
        this.maxTriangles = maxTriangles;
        this.memory = memory;
        long known = length < 0 ? Long.MAX_VALUE : length;
        int chars = 2 * (int) Math.min(1 << 15, known / 2 + 1); // the text and a char; at least 2, so a read has room
        int vertices = (int) Math.min(1024, known / 8 + 1); // "v 0 0 0" and its newline
        int triangles = (int) Math.min(1024, known / 2 + 1); // a corner and its space
        memory.reserve(MemoryGate.chars(chars) + 2 * MemoryGate.doubles(3 * vertices)
                + 2 * MemoryGate.ints(3 * triangles) + 3 * MemoryGate.ints(16));
        text = new char[chars];
        positions = new double[3 * vertices];
        normals = new double[3 * vertices];
        cornerPositions = new int[3 * triangles];
        cornerNormals = new int[3 * triangles];
        facePositions = new int[16];
        faceNormals = new int[16];
        faceUvs = new int[16];
    }

    /** Reads a whole text, without limits. */
    public static MeshData parse(String text) {
        return parse(text, Integer.MAX_VALUE, MemoryGate.UNLIMITED);
    }

    /**
     * Reads a whole text, with at most {@code maxTriangles} triangles, asking {@code memory} before
     * every allocation.
     *
     * @throws TooManyTrianglesException as soon as a face passes the limit
     * @throws ObjFormatException        if the text is not a usable mesh
     */
    public static MeshData parse(String text, int maxTriangles, MemoryGate memory) {
        try {
            return new ObjReader(new StringReader(text), text.length(), maxTriangles, memory).read();
        } catch (IOException e) {
            throw new UncheckedIOException(e); // a StringReader does not throw
        }
    }

    /** Reads the whole of {@code in} (not closed here), without limits; a buffered reader is not needed. */
    public static MeshData read(Reader in) throws IOException {
        return new ObjReader(in, -1, Integer.MAX_VALUE, MemoryGate.UNLIMITED).read();
    }

    private MeshData read() throws IOException {
        int lineStart = 0, scan = 0;
        while (true) {
            int newline = scan;
            while (newline < length && text[newline] != '\n') {
                newline++;
            }
            if (newline < length || endOfInput) {
                if (newline > lineStart || newline < length) {
                    line++;
                    pos = lineStart;
                    lineEnd = newline;
                    statement();
                }
                if (newline >= length) {
                    break;
                }
                lineStart = scan = newline + 1;
                continue;
            }
            // The line runs past the buffered text: keep its start, read more.
            int kept = length - lineStart;
            if (kept == text.length) {
                memory.reserve(MemoryGate.chars(text.length * 2L));
                text = Arrays.copyOf(text, text.length * 2);
            } else if (lineStart > 0) {
                System.arraycopy(text, lineStart, text, 0, kept);
            }
            length = kept;
            lineStart = 0;
            scan = kept;
            int n = in.read(text, length, text.length - length);
            if (n < 0) {
                endOfInput = true;
            } else {
                length += n;
            }
        }
        return result();
    }

    private void statement() {
        if (!nextToken()) {
            return;
        }
        int n = tokenEnd - tokenStart;
        char c0 = text[tokenStart];
        if (n == 1 && c0 == 'v') {
            vertex();
        } else if (n == 1 && c0 == 'f') {
            face();
        } else if (n == 2 && c0 == 'v' && text[tokenStart + 1] == 'n') {
            normal();
        } else if (n == 2 && c0 == 'v' && text[tokenStart + 1] == 't') {
            textureCoordinate();
        }
        // o, g, s, usemtl, mtllib and anything else: ignored
    }

    private void vertex() {
        if (3 * positionCount + 3 > positions.length) {
            memory.reserve(MemoryGate.doubles(positions.length * 2L));
            positions = Arrays.copyOf(positions, positions.length * 2);
        }
        for (int k = 0; k < 3; k++) {
            positions[3 * positionCount + k] = coordinate("vertex");
        }
        positionCount++;
    }

    private void normal() {
        if (3 * normalCount + 3 > normals.length) {
            memory.reserve(MemoryGate.doubles(normals.length * 2L));
            normals = Arrays.copyOf(normals, normals.length * 2);
        }
        double x = coordinate("normal"), y = coordinate("normal"), z = coordinate("normal");
        if (x == 0 && y == 0 && z == 0) {
            throw new ObjFormatException(line, "normal has zero length");
        }
        normals[3 * normalCount] = x;
        normals[3 * normalCount + 1] = y;
        normals[3 * normalCount + 2] = z;
        normalCount++;
    }

    /** {@code vt u [v [w]]}: v defaults to 0, w is ignored. The arrays for them exist from the first one. */
    private void textureCoordinate() {
        if (uvs == null) {
            memory.reserve(MemoryGate.doubles(2L * 64) + MemoryGate.ints(cornerPositions.length));
            uvs = new double[2 * 64];
            cornerUvs = new int[cornerPositions.length];
            Arrays.fill(cornerUvs, 0, cornerCount, -1);
        } else if (2 * uvCount + 2 > uvs.length) {
            memory.reserve(MemoryGate.doubles(uvs.length * 2L));
            uvs = Arrays.copyOf(uvs, uvs.length * 2);
        }
        if (!nextToken()) {
            throw new ObjFormatException(line, "texture coordinate needs at least u");
        }
        double u = textureValue();
        double v = nextToken() ? textureValue() : 0;
        uvs[2 * uvCount] = u;
        uvs[2 * uvCount + 1] = v;
        uvCount++;
    }

    private double textureValue() {
        double value = number(tokenStart, tokenEnd);
        if (!Double.isFinite(value)) {
            throw new ObjFormatException(line, "texture coordinate '" + token() + "' is not finite");
        }
        return value;
    }

    private double coordinate(String what) {
        if (!nextToken()) {
            throw new ObjFormatException(line, what + " needs 3 coordinates");
        }
        double v = number(tokenStart, tokenEnd);
        if (!Double.isFinite(v)) {
            throw new ObjFormatException(line, what + " coordinate '" + token() + "' is not finite");
        }
        return v;
    }

    private void face() {
        int corners = 0;
        int room = maxTriangles - cornerCount / 3; // triangles still allowed
        while (nextToken()) {
            if (corners - 1 > room) { // this corner would make the face's (corners - 1)th triangle
                throw new TooManyTrianglesException(maxTriangles, line);
            }
            if (corners == facePositions.length) {
                memory.reserve(2 * MemoryGate.ints(corners * 2L));
                facePositions = Arrays.copyOf(facePositions, corners * 2);
                faceNormals = Arrays.copyOf(faceNormals, corners * 2);
                faceUvs = Arrays.copyOf(faceUvs, corners * 2);
            }
            corner(corners++);
        }
        if (corners < 3) {
            throw new ObjFormatException(line, "face has " + corners + (corners == 1 ? " vertex" : " vertices")
                    + ", needs at least 3");
        }
        int triangles = corners - 2;
        if (cornerCount + 3 * triangles > cornerPositions.length) {
            int capacity = Math.max(cornerPositions.length * 2, cornerCount + 3 * triangles);
            memory.reserve((cornerUvs != null ? 3 : 2) * MemoryGate.ints(capacity));
            cornerPositions = Arrays.copyOf(cornerPositions, capacity);
            cornerNormals = Arrays.copyOf(cornerNormals, capacity);
            if (cornerUvs != null) {
                cornerUvs = Arrays.copyOf(cornerUvs, capacity);
            }
        }
        for (int k = 1; k + 1 < corners; k++) { // fan around the first corner
            addCorner(0);
            addCorner(k);
            addCorner(k + 1);
        }
    }

    private void addCorner(int k) {
        cornerPositions[cornerCount] = facePositions[k];
        cornerNormals[cornerCount] = faceNormals[k];
        if (cornerUvs != null) {
            cornerUvs[cornerCount] = faceUvs[k];
        }
        cornerCount++;
    }

    /** Parses one corner token: v, v/t, v//n or v/t/n. */
    private void corner(int k) {
        int end = tokenEnd;
        int slash1 = indexOf('/', tokenStart, end);
        int vEnd = slash1 < 0 ? end : slash1;
        facePositions[k] = resolve(integer(tokenStart, vEnd), positionCount, "vertex");
        faceNormals[k] = -1;
        faceUvs[k] = -1;
        if (slash1 >= 0) {
            int slash2 = indexOf('/', slash1 + 1, end);
            int tEnd = slash2 < 0 ? end : slash2;
            if (tEnd > slash1 + 1) {
                int uv = integer(slash1 + 1, tEnd);
                // with no vt at all, an index is checked for form only (as before texture coordinates were read)
                faceUvs[k] = uvs != null ? resolve(uv, uvCount, "texture coordinate") : -1;
            }
            if (slash2 >= 0) {
                faceNormals[k] = resolve(integer(slash2 + 1, end), normalCount, "normal");
            }
        }
        if (faceNormals[k] < 0) {
            everyCornerHasNormal = false;
        }
        if (faceUvs[k] < 0) {
            everyCornerHasUv = false;
        }
    }

    private int indexOf(char c, int from, int end) {
        for (int i = from; i < end; i++) {
            if (text[i] == c) {
                return i;
            }
        }
        return -1;
    }

    /** A 1-based or negative (relative) OBJ index as a 0-based index below {@code count}. */
    private int resolve(int index, int count, String what) {
        if (index == 0) {
            throw new ObjFormatException(line, what + " index 0 is not valid (OBJ indices start at 1)");
        }
        int resolved = index > 0 ? index - 1 : count + index;
        if (resolved < 0 || resolved >= count) {
            String plural = what.equals("vertex") ? "vertices" : what + "s";
            throw new ObjFormatException(line, what + " index " + index + " is out of range ("
                    + count + " " + (count == 1 ? what : plural) + " so far)");
        }
        return resolved;
    }

    private int integer(int start, int end) {
        int i = start;
        boolean negative = false;
        if (i < end && (text[i] == '-' || text[i] == '+')) {
            negative = text[i] == '-';
            i++;
        }
        if (i == end || end - i > 10) {
            throw new ObjFormatException(line, "'" + token() + "' is not a valid index");
        }
        long value = 0;
        for (; i < end; i++) {
            char c = text[i];
            if (c < '0' || c > '9') {
                throw new ObjFormatException(line, "'" + token() + "' is not a valid index");
            }
            value = value * 10 + (c - '0');
        }
        if (value > Integer.MAX_VALUE) {
            throw new ObjFormatException(line, "index in '" + token() + "' is too large");
        }
        return negative ? (int) -value : (int) value;
    }

    /** The number in text[start, end), correctly rounded. */
    private double number(int start, int end) {
        int i = start;
        boolean negative = false;
        if (i < end && (text[i] == '-' || text[i] == '+')) {
            negative = text[i] == '-';
            i++;
        }
        long significand = 0; // unsigned, up to 19 digits
        int significant = 0, exponent = 0, digits = 0;
        boolean wellFormed = true;
        for (; i < end && text[i] >= '0' && text[i] <= '9'; i++, digits++) {
            if (significant > 0 || text[i] != '0') {
                significand = significand * 10 + (text[i] - '0');
                significant++;
            }
        }
        if (i < end && text[i] == '.') {
            for (i++; i < end && text[i] >= '0' && text[i] <= '9'; i++, digits++) {
                if (significant > 0 || text[i] != '0') {
                    significand = significand * 10 + (text[i] - '0');
                    significant++;
                }
                exponent--;
            }
        }
        if (digits > 0 && i < end && (text[i] == 'e' || text[i] == 'E')) {
            i++;
            boolean expNegative = false;
            if (i < end && (text[i] == '-' || text[i] == '+')) {
                expNegative = text[i] == '-';
                i++;
            }
            int e = 0, expDigits = 0;
            for (; i < end && text[i] >= '0' && text[i] <= '9'; i++, expDigits++) {
                if (e < 100_000) {
                    e = e * 10 + (text[i] - '0');
                }
            }
            wellFormed = expDigits > 0;
            exponent += expNegative ? -e : e;
        }
        if (wellFormed && digits > 0 && i == end) {
            if (significant <= 19) {
                double v = DecimalToDouble.toDouble(significand, exponent);
                if (v == v) {
                    return negative ? -v : v;
                }
            }
            return Double.parseDouble(token(start, end)); // a decimal number: it parses
        }
        String token = token(start, end);
        String unsigned = token.startsWith("-") || token.startsWith("+") ? token.substring(1) : token;
        if (unsigned.equals("NaN") || unsigned.equals("Infinity")) {
            return Double.NaN; // the caller says it is not finite
        }
        throw new ObjFormatException(line, "'" + token + "' is not a number");
    }

    /** Moves to the next whitespace-separated token of the line; a '#' ends the line. */
    private boolean nextToken() {
        while (pos < lineEnd && text[pos] <= ' ') {
            pos++;
        }
        if (pos >= lineEnd || text[pos] == '#') {
            pos = lineEnd;
            return false;
        }
        tokenStart = pos;
        while (pos < lineEnd && text[pos] > ' ') {
            pos++;
        }
        tokenEnd = pos;
        return true;
    }

    private String token() {
        return token(tokenStart, tokenEnd);
    }

    private String token(int start, int end) {
        return new String(text, start, end - start);
    }

    private MeshData result() {
        if (uvs != null && everyCornerHasUv && cornerCount > 0) {
            return withUvs();
        }
        long copies = MemoryGate.doubles(3L * positionCount) + MemoryGate.ints(cornerCount);
        if (!everyCornerHasNormal || cornerCount == 0) {
            memory.reserve(copies);
            return new MeshData(Arrays.copyOf(positions, 3 * positionCount),
                    Arrays.copyOf(cornerPositions, cornerCount), null);
        }
        if (normalCount == positionCount && Arrays.equals(cornerPositions, 0, cornerCount, cornerNormals, 0, cornerCount)) {
            // f v//v ...: normal i belongs to vertex i, as OBJ writers usually arrange it
            memory.reserve(copies + MemoryGate.doubles(3L * normalCount));
            return new MeshData(Arrays.copyOf(positions, 3 * positionCount), Arrays.copyOf(cornerPositions, cornerCount),
                    Arrays.copyOf(normals, 3 * normalCount));
        }
        // Otherwise vertices are (position, normal) pairs, numbered in order of first use.
        LongIntMap pairs = new LongIntMap(positionCount, memory);
        memory.reserve(2 * MemoryGate.doubles(3L * positionCount) + MemoryGate.ints(cornerCount));
        double[] outPositions = new double[3 * positionCount];
        double[] outNormals = new double[3 * positionCount];
        int[] indices = new int[cornerCount];
        int vertices = 0;
        for (int c = 0; c < cornerCount; c++) {
            int p = cornerPositions[c], n = cornerNormals[c];
            long key = ((long) p << 32) | n;
            int v = pairs.get(key);
            if (v < 0) {
                v = vertices++;
                pairs.putNew(key, v);
                if (3 * v + 3 > outPositions.length) {
                    memory.reserve(2 * MemoryGate.doubles(outPositions.length * 2L));
                    outPositions = Arrays.copyOf(outPositions, outPositions.length * 2);
                    outNormals = Arrays.copyOf(outNormals, outNormals.length * 2);
                }
                System.arraycopy(positions, 3 * p, outPositions, 3 * v, 3);
                System.arraycopy(normals, 3 * n, outNormals, 3 * v, 3);
            }
            indices[c] = v;
        }
        memory.reserve(2 * MemoryGate.doubles(3L * vertices));
        return new MeshData(Arrays.copyOf(outPositions, 3 * vertices), indices, Arrays.copyOf(outNormals, 3 * vertices));
    }

    /**
     * The mesh when every corner names a texture coordinate: vertices are (position, normal, uv)
     * triples (normal only if every corner has one), numbered in order of first use.
     */
    private MeshData withUvs() {
        boolean withNormals = everyCornerHasNormal;
        LongIntMap attributes = new LongIntMap(positionCount, memory); // (normal, uv) -> id
        LongIntMap triples = new LongIntMap(positionCount, memory); // (position, id) -> vertex
        memory.reserve((withNormals ? 2 : 1) * MemoryGate.doubles(3L * positionCount)
                + MemoryGate.doubles(2L * positionCount) + MemoryGate.ints(cornerCount));
        double[] outPositions = new double[3 * positionCount];
        double[] outNormals = withNormals ? new double[3 * positionCount] : null;
        double[] outUvs = new double[2 * positionCount];
        int[] indices = new int[cornerCount];
        int vertices = 0, ids = 0;
        for (int c = 0; c < cornerCount; c++) {
            int p = cornerPositions[c], n = withNormals ? cornerNormals[c] : 0, t = cornerUvs[c];
            long pair = ((long) n << 32) | t;
            int id = attributes.get(pair);
            if (id < 0) {
                id = ids++;
                attributes.putNew(pair, id);
            }
            long key = ((long) p << 32) | id;
            int v = triples.get(key);
            if (v < 0) {
                v = vertices++;
                triples.putNew(key, v);
                if (3 * v + 3 > outPositions.length) {
                    int grown = outPositions.length * 2;
                    memory.reserve((withNormals ? 2 : 1) * MemoryGate.doubles(grown) + MemoryGate.doubles(grown / 3 * 2));
                    outPositions = Arrays.copyOf(outPositions, grown);
                    outUvs = Arrays.copyOf(outUvs, grown / 3 * 2);
                    if (withNormals) {
                        outNormals = Arrays.copyOf(outNormals, grown);
                    }
                }
                System.arraycopy(positions, 3 * p, outPositions, 3 * v, 3);
                if (withNormals) {
                    System.arraycopy(normals, 3 * n, outNormals, 3 * v, 3);
                }
                outUvs[2 * v] = uvs[2 * t];
                outUvs[2 * v + 1] = uvs[2 * t + 1];
            }
            indices[c] = v;
        }
        memory.reserve((withNormals ? 2 : 1) * MemoryGate.doubles(3L * vertices) + MemoryGate.doubles(2L * vertices));
        return new MeshData(Arrays.copyOf(outPositions, 3 * vertices), indices,
                withNormals ? Arrays.copyOf(outNormals, 3 * vertices) : null, Arrays.copyOf(outUvs, 2 * vertices));
    }
}
