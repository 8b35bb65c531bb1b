package studio.bench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import studio.server.scene.compiling.MeshFiles;
import studio.server.scene.format.ObjectDto;
import studio.server.scene.format.SceneDto;
import studio.server.scene.reading.SceneReader;
import tools.jackson.databind.JsonNode;
import tools.jackson.databind.json.JsonMapper;
import tools.jackson.databind.node.ObjectNode;

/**
 * One benchmark scene written out for all three renderers, in its own folder: our scene file and
 * its mask variant, POV-Ray's {@code scene.pov} and {@code mask.pov}, and a Sunflow script per
 * number of samples per pixel ({@code scene-N.sfs}) and for the mask ({@code mask.sfs}).
 */
record PeerScene(String name, Path dir, ResolvedScene scene, Path ourJson, Path ourMaskJson, Path pov, Path povMask,
                 Map<Integer, Path> sunflow, Path sunflowMask) {

    /**
     * Reads {@code json} (validated as the server reads it) and writes every renderer's files into
     * {@code dir}. Mesh files named in the scene are read from {@code meshFolder} (the scene file's
     * folder) and copied into {@code dir} unless they are there already, for our CLI reads them
     * beside the scene file.
     *
     * @throws IllegalArgumentException if a mesh cannot be read
     */
    static PeerScene write(String name, byte[] json, SceneReader reader, Path dir, Renderers renderers,
                           List<Integer> samples, Path meshFolder) throws IOException {
        Files.createDirectories(dir);
        SceneDto dto = reader.read(json);
        ResolvedScene scene = ResolvedScene.of(dto, renderers.width(), renderers.height(), MeshFiles.in(meshFolder));
        copyMeshFiles(dto, meshFolder, dir);
        ResolvedScene mask = scene.asMask();

        Path ourJson = Files.write(dir.resolve("scene.json"), json);
        Path ourMaskJson = Files.write(dir.resolve("mask.json"), maskJson(json));
        Path pov = Files.writeString(dir.resolve("scene.pov"), PovrayScene.of(scene, name));
        Path povMask = Files.writeString(dir.resolve("mask.pov"), PovrayScene.of(mask, name + ", mask"));
        Map<Integer, Path> sunflow = new LinkedHashMap<>();
        for (int n : samples) {
            Path script = dir.resolve("scene-" + n + ".sfs");
            SunflowScene.of(scene, Renderers.sunflowAaLevel(n), renderers.threads()).write(script);
            sunflow.put(n, script);
        }
        Path sunflowMask = dir.resolve("mask.sfs");
        SunflowScene.of(mask, 0, renderers.threads()).write(sunflowMask);
        return new PeerScene(name, dir, scene, ourJson, ourMaskJson, pov, povMask, sunflow, sunflowMask);
    }

    /** Copies each mesh file the scene names from {@code from} to the same name under {@code to}. */
    static void copyMeshFiles(SceneDto dto, Path from, Path to) throws IOException {
        if (Files.isSameFile(from, to)) {
            return;
        }
        for (ObjectDto o : dto.objects()) {
            if (o instanceof ObjectDto.Mesh mesh && mesh.file() != null) {
                Path target = to.resolve(mesh.file());
                Files.createDirectories(target.getParent());
                Files.copy(from.resolve(mesh.file()), target, java.nio.file.StandardCopyOption.REPLACE_EXISTING);
            }
        }
    }

    /**
     * Our scene file's mask variant, as {@link ResolvedScene#asMask()}: every object's material flat
     * white (planes flat black), no lights, a black background; camera and geometry as they were.
     */
    static byte[] maskJson(byte[] json) {
        JsonMapper mapper = JsonMapper.builder().build();
        ObjectNode root = (ObjectNode) mapper.readTree(json);
        root.putArray("lights");
        root.put("background", "#000000");
        JsonNode objects = root.get("objects");
        if (objects != null) {
            for (JsonNode object : objects) {
                ObjectNode material = ((ObjectNode) object).putObject("material");
                material.put("type", "flat");
                material.put("color", "plane".equals(object.path("type").asString()) ? "#000000" : "#ffffff");
            }
        }
        return mapper.writerWithDefaultPrettyPrinter().writeValueAsBytes(root);
    }
}
