import { meshCache } from '../hooks/useMeshes';
import { scaleToFit } from '../model/obj';
import { useSceneStore } from '../store/sceneStore';
import { ObjFileButton } from './ObjFileButton';

/** Props of {@link AddMeshButton}. */
export interface AddMeshButtonProps {
  /** Shows why a file could not be added, or clears the message with null. */
  onMessage: (message: string | null) => void;
}

/**
 * "+ Mesh": picks an OBJ file and adds it as an inline mesh resting on the floor in front of the
 * camera (clear of the others), scaled so its bounding
 * box's largest side is about 2 m, selected; one undo step. A file that is not a usable OBJ is
 * refused with the line of its first problem.
 */
export function AddMeshButton({ onMessage }: AddMeshButtonProps) {
  const add = (text: string, fileName: string) => {
    // Parsed through the cache, so the views and the preview reuse this very parse.
    const state = meshCache.parseInline(text);
    if (state.status !== 'ready') onMessage(`Cannot add ${fileName}: it is not a usable OBJ mesh (${state.status === 'error' ? state.message : 'unreadable'}).`);
    else if (state.mesh.triangleCount === 0) onMessage(`Cannot add ${fileName}: it has no faces.`);
    else {
      onMessage(null);
      useSceneStore.getState().addMesh(text, scaleToFit(state.mesh));
    }
  };
  return (
    <ObjFileButton
      ariaLabel="Add mesh"
      title="Add a triangle mesh from a Wavefront OBJ file, on the floor in front of the camera, scaled to about 2 m"
      testId="add-mesh"
      onLoad={add}
      onError={onMessage}
    >
      + Mesh
    </ObjFileButton>
  );
}
