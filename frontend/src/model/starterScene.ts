/**
 * The scene the editor starts with when nothing is saved: a copy of `scenes/still-life.json`
 * (the editor is built without the repository's scenes folder; a test keeps the two equal).
 */
import type { Scene } from './types';

export const STARTER_SCENE: Scene = {
  "version": 1,
  "name": "still-life",
  "image": {
    "width": 800,
    "height": 600,
    "format": "png"
  },
  "camera": {
    "position": [4, 3, 6],
    "lookAt": [0, 0.7, 0],
    "up": [0, 1, 0],
    "fov": 40
  },
  "background": "#2a2f38",
  "ambient": 0.07,
  "render": {
    "sampler": "jittered",
    "samples": 16,
    "maxDepth": 6
  },
  "lights": [
    {
      "type": "point",
      "position": [-3, 6, 4],
      "color": "#ffffff",
      "intensity": 0.85
    },
    {
      "type": "point",
      "position": [5, 4, -2],
      "color": "#ffd8a8",
      "intensity": 0.35
    }
  ],
  "objects": [
    {
      "type": "box",
      "center": [0, 0.6, 0],
      "size": [1.2, 1.2, 1.2],
      "rotation": [0, 25, 0],
      "material": {
        "type": "plastic",
        "color": "#c0392b"
      }
    },
    {
      "type": "sphere",
      "center": [-1.6, 0.5, 0.6],
      "radius": 0.5,
      "material": {
        "type": "metal",
        "color": "#d4af37"
      }
    },
    {
      "type": "sphere",
      "center": [1.4, 0.45, 1.0],
      "radius": 0.45,
      "material": {
        "type": "mirror"
      }
    },
    {
      "type": "sphere",
      "center": [0.2, 1.55, 0.1],
      "radius": 0.35,
      "material": {
        "type": "chalk",
        "color": "#ecf0f1"
      }
    },
    {
      "type": "sphere",
      "center": [0.9, 0.3, -1.3],
      "radius": 0.3,
      "material": {
        "type": "plastic",
        "color": "#2e86c1"
      }
    },
    {
      "type": "plane",
      "point": [0, 0, 0],
      "normal": [0, 1, 0],
      "material": {
        "type": "chalk",
        "color": "#c8c0b0"
      }
    }
  ]
};
