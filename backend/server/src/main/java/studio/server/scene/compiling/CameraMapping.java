package studio.server.scene.compiling;

import static studio.server.scene.compiling.FormatValues.or;
import static studio.server.scene.compiling.FormatValues.vec;

import studio.engine.camera.Camera;
import studio.engine.math.Vec3;
import studio.server.scene.format.CameraDto;
import studio.server.scene.format.SceneDefaults;

/** The camera, and the rules across its fields: a target apart from it, an up not along the view. */
final class CameraMapping {

    private CameraMapping() {
    }

    /** The camera, or null (and a problem at the field at fault). */
    static Camera of(CameraDto dto, MappingProblems problems) {
        CameraDto c = dto != null ? dto : new CameraDto(null, null, null, null);
        return problems.attempt("camera", () -> camera(c));
    }

    private static Camera camera(CameraDto c) {
        Vec3 position = vec(or(c.position(), SceneDefaults.CAMERA_POSITION));
        Vec3 lookAt = vec(or(c.lookAt(), SceneDefaults.CAMERA_LOOK_AT));
        Vec3 up = vec(or(c.up(), SceneDefaults.CAMERA_UP));
        Vec3 view = lookAt.minus(position);
        // compared as numbers, not by Vec3.equals: a record's first equals spins method handles (some
        // 10 ms of a cold command line), and it tells 0.0 from -0.0, which name the same point
        if (view.x() == 0 && view.y() == 0 && view.z() == 0) {
            throw new MappingProblems.FieldException("camera.lookAt", "must differ from camera.position");
        }
        if (up.cross(view.normalized()).length() <= 1e-9 * up.length()) {
            throw new MappingProblems.FieldException("camera.up", "is parallel to the view direction (lookAt - "
                    + "position); the camera's roll is undefined");
        }
        return new Camera(position, lookAt, up, or(c.fov(), SceneDefaults.CAMERA_FOV_DEGREES));
    }
}
