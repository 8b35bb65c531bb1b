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
 * <p>The text is read line by line and token by token in place ({@link ObjLines}); the faces'
 * corners become the mesh's vertices in {@link ObjCorners}.
 */
public final class ObjReader {

    private final ObjLines lines;
    private final int maxTriangles;
    private final MemoryGate memory;

    private double[] positions;
    private int positionCount;
    private double[] normals;
    private int normalCount;
    /** Texture coordinates, u and v per vt: null until the first one. */
    private double[] uvs;
    private int uvCount;
    private final ObjCorners corners;
    /** The current face's corners: position, normal and uv indices (-1: none). */
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
        this.maxTriangles = maxTriangles;
        this.memory = memory;
        long known = length < 0 ? Long.MAX_VALUE : length;
        int chars = 2 * (int) Math.min(1 << 15, known / 2 + 1); // the text and a char; at least 2, so a read has room
        int vertices = (int) Math.min(1024, known / 8 + 1); // "v 0 0 0" and its newline
        int triangles = (int) Math.min(1024, known / 2 + 1); // a corner and its space
        lines = new ObjLines(in, chars, memory);
        corners = new ObjCorners(triangles, memory);
        memory.reserve(2 * MemoryGate.doubles(3 * vertices) + 3 * MemoryGate.ints(16));
        positions = new double[3 * vertices];
        normals = new double[3 * vertices];
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
        while (lines.nextLine()) {
            statement();
        }
        return corners.mesh(positions, positionCount, normals, normalCount, uvs);
    }

    private void statement() {
        if (!lines.nextToken()) {
            return;
        }
        if (lines.tokenIs('v', (char) 0)) {
            vertex();
        } else if (lines.tokenIs('f', (char) 0)) {
            face();
        } else if (lines.tokenIs('v', 'n')) {
            normal();
        } else if (lines.tokenIs('v', 't')) {
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
            throw new ObjFormatException(lines.line(), "normal has zero length");
        }
        normals[3 * normalCount] = x;
        normals[3 * normalCount + 1] = y;
        normals[3 * normalCount + 2] = z;
        normalCount++;
    }

    /** {@code vt u [v [w]]}: v defaults to 0, w is ignored. The arrays for them exist from the first one. */
    private void textureCoordinate() {
        if (uvs == null) {
            memory.reserve(MemoryGate.doubles(2L * 64));
            uvs = new double[2 * 64];
            corners.trackUvs();
        } else if (2 * uvCount + 2 > uvs.length) {
            memory.reserve(MemoryGate.doubles(uvs.length * 2L));
            uvs = Arrays.copyOf(uvs, uvs.length * 2);
        }
        if (!lines.nextToken()) {
            throw new ObjFormatException(lines.line(), "texture coordinate needs at least u");
        }
        double u = textureValue();
        double v = lines.nextToken() ? textureValue() : 0;
        uvs[2 * uvCount] = u;
        uvs[2 * uvCount + 1] = v;
        uvCount++;
    }

    private double textureValue() {
        double value = lines.number();
        if (!Double.isFinite(value)) {
            throw new ObjFormatException(lines.line(), "texture coordinate '" + lines.token() + "' is not finite");
        }
        return value;
    }

    private double coordinate(String what) {
        if (!lines.nextToken()) {
            throw new ObjFormatException(lines.line(), what + " needs 3 coordinates");
        }
        double v = lines.number();
        if (!Double.isFinite(v)) {
            throw new ObjFormatException(lines.line(), what + " coordinate '" + lines.token() + "' is not finite");
        }
        return v;
    }

    private void face() {
        int count = 0;
        int room = maxTriangles - corners.triangles(); // triangles still allowed
        while (lines.nextToken()) {
            if (count - 1 > room) { // this corner would make the face's (count - 1)th triangle
                throw new TooManyTrianglesException(maxTriangles, lines.line());
            }
            if (count == facePositions.length) {
                memory.reserve(3 * MemoryGate.ints(count * 2L));
                facePositions = Arrays.copyOf(facePositions, count * 2);
                faceNormals = Arrays.copyOf(faceNormals, count * 2);
                faceUvs = Arrays.copyOf(faceUvs, count * 2);
            }
            corner(count++);
        }
        if (count < 3) {
            throw new ObjFormatException(lines.line(), "face has " + count + (count == 1 ? " vertex" : " vertices")
                    + ", needs at least 3");
        }
        corners.addFace(facePositions, faceNormals, faceUvs, count);
    }

    /** Parses one corner token: v, v/t, v//n or v/t/n. */
    private void corner(int k) {
        int start = lines.tokenStart(), end = lines.tokenEnd();
        int slash1 = lines.slash(start);
        facePositions[k] = resolve(lines.integer(start, slash1 < 0 ? end : slash1), positionCount, "vertex");
        faceNormals[k] = -1;
        faceUvs[k] = -1;
        if (slash1 >= 0) {
            int slash2 = lines.slash(slash1 + 1);
            int tEnd = slash2 < 0 ? end : slash2;
            if (tEnd > slash1 + 1) {
                int uv = lines.integer(slash1 + 1, tEnd);
                // with no vt at all, an index is checked for form only (as before texture coordinates were read)
                faceUvs[k] = uvs != null ? resolve(uv, uvCount, "texture coordinate") : -1;
            }
            if (slash2 >= 0) {
                faceNormals[k] = resolve(lines.integer(slash2 + 1, end), normalCount, "normal");
            }
        }
    }

    /** A 1-based or negative (relative) OBJ index as a 0-based index below {@code count}. */
    private int resolve(int index, int count, String what) {
        if (index == 0) {
            throw new ObjFormatException(lines.line(), what + " index 0 is not valid (OBJ indices start at 1)");
        }
        int resolved = index > 0 ? index - 1 : count + index;
        if (resolved < 0 || resolved >= count) {
            String plural = what.equals("vertex") ? "vertices" : what + "s";
            throw new ObjFormatException(lines.line(), what + " index " + index + " is out of range ("
                    + count + " " + (count == 1 ? what : plural) + " so far)");
        }
        return resolved;
    }
}
