package studio.engine.mesh;

import java.io.IOException;
import java.io.UncheckedIOException;

/**
 * Writes a {@link MeshData} as Wavefront OBJ text: {@code v} lines, {@code vn} lines if the mesh
 * has normals, and one {@code f} per triangle ({@code f a//a b//b c//c} with normals).
 *
 * <p>By default numbers are written with {@link Double#toString}, so {@link ObjReader} reads back
 * exactly the same mesh. With a number of decimals they are rounded to that many places, as
 * modelling tools write OBJ (Blender: 6), which gives files half the size that every OBJ reader
 * parses quickly (used for benchmark scenes shared with other renderers).
 */
public final class ObjWriter {

    /** Write every number exactly. */
    public static final int EXACT = -1;
    private static final double[] POWERS = {1, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9};

    private ObjWriter() {
    }

    public static void write(MeshData mesh, Appendable out) throws IOException {
        write(mesh, out, EXACT);
    }

    /** @param decimals places after the point, 0..9, or {@link #EXACT} */
    public static void write(MeshData mesh, Appendable out, int decimals) throws IOException {
        if (decimals != EXACT && (decimals < 0 || decimals > 9)) {
            throw new IllegalArgumentException("decimals must be 0..9 or EXACT: " + decimals);
        }
        StringBuilder line = new StringBuilder(64);
        double[] p = mesh.positions();
        for (int i = 0; i < p.length; i += 3) {
            line.setLength(0);
            line.append('v');
            for (int k = 0; k < 3; k++) {
                appendNumber(line.append(' '), p[i + k], decimals);
            }
            out.append(line.append('\n'));
        }
        double[] n = mesh.normals();
        if (n != null) {
            for (int i = 0; i < n.length; i += 3) {
                line.setLength(0);
                line.append("vn");
                for (int k = 0; k < 3; k++) {
                    appendNumber(line.append(' '), n[i + k], decimals);
                }
                out.append(line.append('\n'));
            }
        }
        int[] f = mesh.indices();
        for (int i = 0; i < f.length; i += 3) {
            line.setLength(0);
            line.append('f');
            for (int k = 0; k < 3; k++) {
                int index = f[i + k] + 1;
                line.append(' ').append(index);
                if (n != null) {
                    line.append("//").append(index);
                }
            }
            out.append(line.append('\n'));
        }
    }

    /** The mesh as OBJ text, numbers exact. */
    public static String toString(MeshData mesh) {
        StringBuilder out = new StringBuilder(mesh.vertexCount() * 60 + mesh.triangleCount() * 30);
        try {
            write(mesh, out);
        } catch (IOException e) {
            throw new UncheckedIOException(e); // a StringBuilder does not throw
        }
        return out.toString();
    }

    /** x rounded to {@code decimals} places, trailing zeros dropped; exactly if EXACT or too large. */
    private static void appendNumber(StringBuilder out, double x, int decimals) {
        double scale = decimals == EXACT ? 0 : POWERS[decimals];
        if (decimals == EXACT || !(Math.abs(x) * scale < 1e17)) {
            out.append(x);
            return;
        }
        long scaled = Math.round(Math.abs(x) * scale);
        if (scaled == 0) {
            out.append('0');
            return;
        }
        if (x < 0) {
            out.append('-');
        }
        long unit = (long) scale;
        out.append(scaled / unit);
        long fraction = scaled % unit;
        if (fraction == 0) {
            return;
        }
        int places = decimals;
        while (fraction % 10 == 0) {
            fraction /= 10;
            places--;
        }
        out.append('.');
        for (; places > 1 && fraction < POWERS[places - 1]; places--) { // leading zeros of the fraction
            out.append('0');
        }
        out.append(fraction);
    }
}
