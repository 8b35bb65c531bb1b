package studio.bench;

/**
 * Field-of-view conversions between the scene format (vertical fov, as three.js) and the peers
 * (POV-Ray's {@code angle} and Sunflow's pinhole {@code fov} are horizontal).
 */
public final class CameraMath {

    private CameraMath() {
    }

    /** The horizontal field of view, in degrees, of an image of this aspect (width / height). */
    public static double horizontalFovDegrees(double verticalFovDegrees, double aspect) {
        double tanHalf = Math.tan(Math.toRadians(verticalFovDegrees) / 2);
        return Math.toDegrees(2 * Math.atan(aspect * tanHalf));
    }

    /** The vertical field of view, in degrees, of an image of this aspect whose horizontal one is given. */
    public static double verticalFovDegrees(double horizontalFovDegrees, double aspect) {
        double tanHalf = Math.tan(Math.toRadians(horizontalFovDegrees) / 2);
        return Math.toDegrees(2 * Math.atan(tanHalf / aspect));
    }
}
