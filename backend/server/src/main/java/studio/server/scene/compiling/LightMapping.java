package studio.server.scene.compiling;

import static studio.server.scene.compiling.FormatValues.or;
import static studio.server.scene.compiling.FormatValues.vec;

import java.util.ArrayList;
import java.util.List;

import studio.engine.light.AreaLight;
import studio.engine.light.Light;
import studio.engine.light.PointLight;
import studio.engine.light.SphereLight;
import studio.engine.math.Rgb;
import studio.engine.math.Vec3;
import studio.server.scene.format.LightDto;
import studio.server.scene.format.SceneDefaults;
import studio.server.scene.format.SceneLimits;

/**
 * The lights: the default light when a scene has no "lights" field, none for an empty list. A
 * point light of radius 0 is the engine's {@link PointLight}, of a larger radius a
 * {@link SphereLight}; an area light an {@link AreaLight}.
 */
final class LightMapping {

    private LightMapping() {
    }

    /** The lights up to the server's limit (and a problem for the rest, or for an area light aimed at itself). */
    static List<Light> of(List<LightDto> dtos, SceneLimits limits, MappingProblems problems) {
        List<Light> lights = new ArrayList<>();
        if (dtos == null) {
            lights.add(new PointLight(vec(SceneDefaults.LIGHT_POSITION), Colors.linear(SceneDefaults.LIGHT_COLOR),
                    SceneDefaults.LIGHT_INTENSITY, false));
            return lights;
        }
        problems.atMost("lights", dtos.size(), limits.maxLights(), "lights");
        for (int i = 0; i < dtos.size() && i < limits.maxLights(); i++) {
            LightDto dto = dtos.get(i);
            Light light = dto instanceof LightDto.Area a ? area(a, "lights[" + i + "]", problems)
                    : point((LightDto.Point) dto);
            if (light != null) {
                lights.add(light);
            }
        }
        return lights;
    }

    private static Light point(LightDto.Point l) {
        Vec3 position = vec(or(l.position(), SceneDefaults.LIGHT_POSITION));
        Rgb color = Colors.linear(or(l.color(), SceneDefaults.LIGHT_COLOR));
        double intensity = or(l.intensity(), SceneDefaults.LIGHT_INTENSITY), radius = or(l.radius(), SceneDefaults.LIGHT_RADIUS);
        boolean falloff = Boolean.TRUE.equals(l.falloff());
        return radius > 0 ? new SphereLight(position, radius, color, intensity, falloff)
                : new PointLight(position, color, intensity, falloff);
    }

    private static Light area(LightDto.Area l, String at, MappingProblems problems) {
        Vec3 position = vec(or(l.position(), SceneDefaults.LIGHT_POSITION));
        Vec3 lookAt = vec(or(l.lookAt(), SceneDefaults.AREA_LIGHT_LOOK_AT));
        // compared as numbers (as the camera's): 0.0 and -0.0 name the same point
        if (position.x() == lookAt.x() && position.y() == lookAt.y() && position.z() == lookAt.z()) {
            problems.add(at + ".lookAt", "must differ from " + at + ".position");
            return null;
        }
        List<Double> size = or(l.size(), SceneDefaults.AREA_LIGHT_SIZE);
        return new AreaLight(position, size.get(0), size.get(1), lookAt,
                Colors.linear(or(l.color(), SceneDefaults.LIGHT_COLOR)), or(l.intensity(), SceneDefaults.LIGHT_INTENSITY),
                Boolean.TRUE.equals(l.falloff()), Boolean.TRUE.equals(l.twoSided()));
    }
}
