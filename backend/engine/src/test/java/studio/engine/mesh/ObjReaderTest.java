package studio.engine.mesh;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.StringReader;
import java.util.Random;

import org.junit.jupiter.api.Test;

import studio.engine.memory.CountingGate;

/** Wavefront OBJ: the statement and index forms read, and the problems reported with their line. */
class ObjReaderTest {

    private static final String SQUARE = """
            # a unit square in z=0
            v 0 0 0
            v 1 0 0
            v 1 1 0
            v 0 1 0
            """;

    @Test
    void readsVerticesAndTriangles() {
        MeshData mesh = ObjReader.parse(SQUARE + "f 1 2 3\nf 1 3 4\n");

        assertArrayEquals(new double[] {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, mesh.positions());
        assertArrayEquals(new int[] {0, 1, 2, 0, 2, 3}, mesh.indices());
        assertNull(mesh.normals());
    }

    @Test
    void readsEveryCornerFormAndRelativeIndices() {
        String text = SQUARE + """
                vt 0 0
                vt 1 0
                vt 1 1
                f 1/1 2/2 3/3
                f -4 -2 -1
                f 1/1/1 2/2/1 3/3/1
                """.replace("f 1/1/1 2/2/1 3/3/1", "f 1/1 3/3 4/1");

        MeshData mesh = ObjReader.parse(text);

        assertArrayEquals(new int[] {0, 1, 2, 0, 2, 3, 0, 2, 3}, mesh.indices());
    }

    @Test
    void polygonsAreFannedAroundTheirFirstCorner() {
        String text = SQUARE + "v 0.5 1.5 0\nf 1 2 3 5 4\n";

        MeshData mesh = ObjReader.parse(text);

        assertArrayEquals(new int[] {0, 1, 2, 0, 2, 4, 0, 4, 3}, mesh.indices());
    }

    @Test
    void ignoresCommentsBlankLinesGroupsMaterialsAndUnknownStatementsAndAcceptsCrlfAndW() {
        String text = "mtllib scene.mtl\r\no thing\r\n\r\n   \r\ng part\r\ns 1\r\nusemtl red\r\n"
                + "v 0 0 0 1.0\r\nv 1 0 0 # trailing comment\r\nv 0 1 0\r\ncstype bspline\r\nf 1 2 3\r\n";

        MeshData mesh = ObjReader.parse(text);

        assertEquals(3, mesh.vertexCount());
        assertArrayEquals(new int[] {0, 1, 2}, mesh.indices());
    }

    @Test
    void normalsAreKeptPerVertexAndAPositionWithTwoNormalsBecomesTwoVertices() {
        String text = SQUARE + """
                vn 0 0 1
                vn 0 0 2
                f 1//1 2//1 3//1
                f 1//2 3//2 4//2
                """;

        MeshData mesh = ObjReader.parse(text);

        // Vertices: (1,n1) (2,n1) (3,n1) (1,n2) (3,n2) (4,n2)
        assertEquals(6, mesh.vertexCount());
        assertArrayEquals(new int[] {0, 1, 2, 3, 4, 5}, mesh.indices());
        assertArrayEquals(new double[] {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 2, 0, 0, 2, 0, 0, 2}, mesh.normals());
        assertArrayEquals(new double[] {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0}, mesh.positions());
    }

    @Test
    void normalsAreDroppedWhenSomeCornerHasNone() {
        MeshData mesh = ObjReader.parse(SQUARE + "vn 0 0 1\nf 1//1 2//1 3//1\nf 1 3 4\n");

        assertNull(mesh.normals());
        assertEquals(4, mesh.vertexCount());
    }

    @Test
    void numbersAreReadExactlyInEveryNotation() {
        MeshData mesh = ObjReader.parse("v 0.1 -2.5e-3 +7\nv 1E2 123456789012345678 .5\nv -0 1e-320 0.30000000000000004\n");

        assertArrayEquals(new double[] {0.1, -2.5e-3, 7, 100, 123456789012345678.0, 0.5, -0.0, 1e-320, 0.30000000000000004},
                mesh.positions());
        assertEquals(Double.doubleToRawLongBits(-0.0), Double.doubleToRawLongBits(mesh.positions()[6]));
    }

    @Test
    void randomDoublesSurviveWritingAndReadingBitForBit() {
        Random random = new Random(3);
        double[] positions = new double[3000];
        for (int i = 0; i < positions.length; i++) {
            positions[i] = switch (i % 3) {
                case 0 -> random.nextGaussian();
                case 1 -> (random.nextDouble() - 0.5) * Math.pow(10, random.nextInt(40) - 20);
                default -> random.nextInt(2000) / 8.0;
            };
        }
        int[] indices = new int[999];
        for (int i = 0; i < indices.length; i++) {
            indices[i] = random.nextInt(1000);
        }
        MeshData mesh = new MeshData(positions, indices, null);

        MeshData back = ObjReader.parse(ObjWriter.toString(mesh));

        assertArrayEquals(positions, back.positions());
        assertArrayEquals(indices, back.indices());
    }

    @Test
    void writtenMeshWithNormalsReadsBackTheSame() throws IOException {
        MeshData sphere = MeshShapes.icosphere(2);

        MeshData back = ObjReader.read(new StringReader(ObjWriter.toString(sphere)));

        assertArrayEquals(sphere.positions(), back.positions());
        assertArrayEquals(sphere.indices(), back.indices());
        assertArrayEquals(sphere.normals(), back.normals());
    }

    @Test
    void roundedOutputHasTheRequestedDecimalsAndReadsBackWithinHalfAUnit() throws IOException {
        double[] positions = {0.000123, -1.5, 2, 1234.5678915, -0.0000004, 1e30, 0.1, 0.7, -9.9999999};
        MeshData mesh = new MeshData(positions, new int[] {0, 1, 2}, null);
        StringBuilder text = new StringBuilder();

        ObjWriter.write(mesh, text, 6);

        assertTrue(text.toString().startsWith("v 0.000123 -1.5 2\nv 1234.567892 0 1.0E30\nv 0.1 0.7 -10\n"), text.toString());
        MeshData back = ObjReader.parse(text.toString());
        for (int i = 0; i < positions.length; i++) {
            assertEquals(positions[i], back.positions()[i], 0.5e-6 * (1 + 1e-9) * Math.max(1, Math.abs(positions[i]) * 1e-9));
        }
    }

    @Test
    void readerLargerThanOneBufferIsReadWhole() throws IOException {
        MeshData knot = MeshShapes.torusKnot(2, 3, 120, 40); // about 1 MB of text

        MeshData back = ObjReader.read(new StringReader(ObjWriter.toString(knot)));

        assertEquals(knot.triangleCount(), back.triangleCount());
        assertArrayEquals(knot.positions(), back.positions());
    }

    @Test
    void aLineLongerThanTheReadBufferIsReadWhole() throws IOException {
        int corners = 30_000; // about 170 kB on one line
        StringBuilder text = new StringBuilder();
        for (int i = 0; i < corners; i++) {
            double angle = 2 * Math.PI * i / corners;
            text.append("v ").append(Math.cos(angle)).append(' ').append(Math.sin(angle)).append(" 0\n");
        }
        text.append("f");
        for (int i = 1; i <= corners; i++) {
            text.append(' ').append(i);
        }

        MeshData mesh = ObjReader.read(new StringReader(text.toString()));

        assertEquals(corners - 2, mesh.triangleCount());
        assertEquals(corners, mesh.indices()[mesh.indices().length - 1] + 1);
    }

    @Test
    void nonFiniteCoordinateIsReportedWithItsLine() {
        ObjFormatException nan = assertThrows(ObjFormatException.class, () -> ObjReader.parse(SQUARE + "v 1 NaN 0\n"));
        ObjFormatException huge = assertThrows(ObjFormatException.class, () -> ObjReader.parse("v 1e999 0 0\n"));
        ObjFormatException garbage = assertThrows(ObjFormatException.class, () -> ObjReader.parse("\nv 1 2 x3\n"));

        assertEquals(6, nan.line());
        assertTrue(nan.getMessage().startsWith("OBJ line 6: ") && nan.getMessage().contains("not finite"), nan.getMessage());
        assertEquals(1, huge.line());
        assertEquals(2, garbage.line());
        assertTrue(garbage.getMessage().contains("'x3' is not a number"), garbage.getMessage());
    }

    @Test
    void numbersAreDecimalOnly() {
        // Double.parseDouble would take all of these
        for (String number : new String[] {"0x1p3", "0X1.8P1", "1.5f", "2d", "1e3D"}) {
            ObjFormatException e = assertThrows(ObjFormatException.class,
                    () -> ObjReader.parse("\nv " + number + " 0 0\n"), number);
            assertEquals(2, e.line());
            assertTrue(e.getMessage().contains("'" + number + "' is not a number"), e.getMessage());
        }
        assertEquals(1500.0, ObjReader.parse("v 1.5e3 0 0\n").positions()[0]);
    }

    @Test
    void stopsAtTheTriangleLimitWithoutReadingOn() {
        // One polygon of a million corners (999,998 triangles in its fan), and a bad line after it
        String text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf" + " 1".repeat(1_000_000) + "\nf 1 2 x\n";
        CountingGate gate = new CountingGate();

        TooManyTrianglesException e = assertThrows(TooManyTrianglesException.class,
                () -> ObjReader.parse(text, 1000, gate));

        assertEquals(4, e.line());
        assertEquals(1000, e.limit());
        // the line is buffered (4 MiB of chars, with its growth 8 MiB); reading the whole face would take 70 MiB more
        assertTrue(gate.granted() < 10 << 20, "granted " + gate.granted());
        assertEquals(1, ObjReader.parse(SQUARE + "f 1 2 3\n", 1, gate).triangleCount());
        assertThrows(TooManyTrianglesException.class, () -> ObjReader.parse(SQUARE + "f 1 2 3 4\n", 1, gate));
        assertThrows(TooManyTrianglesException.class, () -> ObjReader.parse(SQUARE + "f 1 2 3\nf 1 3 4\n", 1, gate));
    }

    @Test
    void asksTheGateBeforeAllocatingWhatItReads() {
        MeshData knot = MeshShapes.torusKnot(2, 3, 400, 100);
        StringBuilder shared = new StringBuilder(ObjWriter.toString(knot));
        // the same, but each corner's normal is another vertex's: vertices become (position, normal) pairs
        StringBuilder pairs = new StringBuilder(ObjWriter.toString(new MeshData(knot.positions(), new int[0],
                knot.normals())));
        int vertices = knot.vertexCount();
        for (int i = 0; i < knot.indices().length; i += 3) {
            pairs.append('f');
            for (int k = 0; k < 3; k++) {
                int v = knot.indices()[i + k];
                pairs.append(' ').append(v + 1).append("//").append((v + 1) % vertices + 1);
            }
            pairs.append('\n');
        }
        for (String text : new String[] {shared.toString(), pairs.toString(), "v 0 0 0\n".repeat(100_000)}) {
            CountingGate gate = new CountingGate();
            long allocated = CountingGate.allocatedBy(() -> ObjReader.parse(text, Integer.MAX_VALUE, gate));

            long numbers = numberParsing(text);
            assertTrue(allocated <= gate.granted() + numbers + CountingGate.SLACK, allocated + " allocated, "
                    + gate.granted() + " granted, " + numbers + " parsing the numbers");
            assertTrue(gate.granted() < 2 * allocated, "granted " + gate.granted() + " for " + allocated);
        }
    }

    @Test
    void aGateThatRefusesStopsTheReaderBeforeItAllocatesMore() {
        String knot = ObjWriter.toString(MeshShapes.torusKnot(2, 3, 400, 100));
        // faces alone (indices are read without allocating): only what the gate granted is allocated
        String faces = "v 0 0 0\nv 1 0 0\nv 0 1 0\n" + "f 1 2 3\n".repeat(300_000);
        for (String text : new String[] {knot, faces}) {
            CountingGate gate = new CountingGate(1 << 20);

            long allocated = CountingGate.allocatedBy(() -> ObjReader.parse(text, Integer.MAX_VALUE, gate));

            long numbers = numberParsing(text);
            assertTrue(allocated <= (1 << 20) + numbers + CountingGate.SLACK, "allocated " + allocated + ", "
                    + numbers + " parsing the numbers");
        }
    }

    /**
     * What the JDK's number parsing allocates for the text's numbers, as the reader calls it (a String
     * of each token, then {@link Double#parseDouble}): short-lived, a token at a time, and not what the
     * gate is asked for (it is asked for what the reader keeps).
     */
    private static long numberParsing(String text) {
        char[] chars = text.toCharArray();
        int[] starts = new int[chars.length / 2 + 1], ends = new int[starts.length];
        int count = 0, lineStart = 0;
        for (int i = 0; i <= chars.length; i++) {
            if (i == chars.length || chars[i] == '\n') {
                if (lineStart < chars.length && chars[lineStart] == 'v') {
                    int j = lineStart;
                    while (j < i && chars[j] != ' ') {
                        j++;
                    }
                    while (j < i) {
                        int start = ++j;
                        while (j < i && chars[j] != ' ') {
                            j++;
                        }
                        starts[count] = start;
                        ends[count++] = j;
                    }
                }
                lineStart = i + 1;
            }
        }
        int n = count;
        double[] sink = new double[1];
        return CountingGate.allocatedBy(() -> {
            for (int k = 0; k < n; k++) {
                sink[0] += Double.parseDouble(new String(chars, starts[k], ends[k] - starts[k]));
            }
        });
    }

    @Test
    void vertexWithTooFewCoordinatesAndZeroNormalAreReported() {
        ObjFormatException shortVertex = assertThrows(ObjFormatException.class, () -> ObjReader.parse("v 1 2\n"));
        ObjFormatException zeroNormal = assertThrows(ObjFormatException.class, () -> ObjReader.parse("vn 0 0 0\n"));

        assertTrue(shortVertex.getMessage().contains("line 1") && shortVertex.getMessage().contains("3 coordinates"));
        assertTrue(zeroNormal.getMessage().contains("zero length"), zeroNormal.getMessage());
    }

    @Test
    void indexOutOfRangeZeroOrNotANumberIsReportedWithItsLine() {
        ObjFormatException high = assertThrows(ObjFormatException.class, () -> ObjReader.parse(SQUARE + "f 1 2 5\n"));
        ObjFormatException relative = assertThrows(ObjFormatException.class, () -> ObjReader.parse(SQUARE + "f -5 1 2\n"));
        ObjFormatException zero = assertThrows(ObjFormatException.class, () -> ObjReader.parse(SQUARE + "f 0 1 2\n"));
        ObjFormatException normal = assertThrows(ObjFormatException.class, () -> ObjReader.parse(SQUARE + "f 1//1 2//1 3//1\n"));
        ObjFormatException word = assertThrows(ObjFormatException.class, () -> ObjReader.parse(SQUARE + "f 1 2 three\n"));
        ObjFormatException later = assertThrows(ObjFormatException.class, () -> ObjReader.parse("v 0 0 0\nf 1 2 3\nv 1 0 0\nv 0 1 0\n"));

        assertEquals(6, high.line());
        assertTrue(high.getMessage().contains("vertex index 5 is out of range (4 vertices so far)"), high.getMessage());
        assertTrue(relative.getMessage().contains("vertex index -5 is out of range"), relative.getMessage());
        assertTrue(zero.getMessage().contains("index 0 is not valid"), zero.getMessage());
        assertTrue(normal.getMessage().contains("normal index 1 is out of range (0 normals so far)"), normal.getMessage());
        assertTrue(word.getMessage().contains("'three' is not a valid index"), word.getMessage());
        assertEquals(2, later.line());
    }

    @Test
    void faceWithFewerThanThreeVerticesIsReportedWithItsLine() {
        ObjFormatException two = assertThrows(ObjFormatException.class, () -> ObjReader.parse(SQUARE + "f 1 2 3\nf 1 2\n"));
        ObjFormatException none = assertThrows(ObjFormatException.class, () -> ObjReader.parse("f\n"));

        assertEquals(7, two.line());
        assertTrue(two.getMessage().contains("face has 2 vertices, needs at least 3"), two.getMessage());
        assertTrue(none.getMessage().contains("face has 0 vertices"), none.getMessage());
    }

    @Test
    void emptyTextIsAnEmptyMesh() {
        MeshData mesh = ObjReader.parse("# nothing\n");

        assertEquals(0, mesh.vertexCount());
        assertEquals(0, mesh.triangleCount());
    }
}
