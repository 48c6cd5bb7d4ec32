// One classic (non-module) script with three.js, its glTF loader and orbit controls, so the
// report opens from file:// where browsers refuse to load ES modules.
import * as THREE from 'three';
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';

window.THREE = Object.assign({}, THREE, { GLTFLoader, OrbitControls });
