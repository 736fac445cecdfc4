#version 150
#ifdef GL_ES
#ifdef GL_FRAGMENT_PRECISION_HIGH
precision highp float;
precision highp sampler2D;
precision highp sampler3D;
#else
precision mediump float;
precision mediump sampler2D;
precision mediump sampler3D;
#endif
#define texelFetchBuffer texelFetch
#define texture1D texture
#define texture2D texture
#define texture3D texture
#else // GL_ES
#define highp
#define mediump
#define lowp
#if __VERSION__ == 150
#define texelFetchBuffer texelFetch
#define texture1D texture
#define texture2D texture
#define texture3D texture
#endif
#endif // GL_ES
#define varying in


/*=========================================================================

  Program:   Visualization Toolkit
  Module:    vtkPolyDataFS.glsl

  Copyright (c) Ken Martin, Will Schroeder, Bill Lorensen
  All rights reserved.
  See Copyright.txt or http://www.kitware.com/Copyright.htm for details.

     This software is distributed WITHOUT ANY WARRANTY; without even
     the implied warranty of MERCHANTABILITY or FITNESS FOR A PARTICULAR
     PURPOSE.  See the above copyright notice for more information.

=========================================================================*/
// Template for the polydata mappers fragment shader

uniform int PrimitiveIDOffset;



// VC position of this fragment
in vec4 vertexVCVSOutput;

// Camera prop
uniform int cameraParallel;


// optional color passed in from the vertex shader, vertexColor
uniform float ambientIntensity; // the material ambient
uniform float diffuseIntensity; // the material diffuse
uniform float opacityUniform; // the fragment opacity
uniform vec3 ambientColorUniform; // ambient color
uniform vec3 diffuseColorUniform; // diffuse color
uniform float specularIntensity; // the material specular intensity
uniform vec3 specularColorUniform; // intensity weighted color
uniform float specularPowerUniform;


// optional surface normal declaration
//VTK::Normal::Dec

// extra lighting parameters
uniform vec3 shadelabKd;
uniform vec3 lightColor0;
  uniform vec3 lightDirectionVC0; // normalized


// Texture maps
//VTK::TMap::Dec

// Texture coordinates
//VTK::TCoord::Dec

// picking support
//VTK::Picking::Dec

// Depth Peeling Support
//VTK::DepthPeeling::Dec

// clipping plane vars
//VTK::Clip::Dec

// the output of this shader
// The 8-bit capture: k = round(255*clamp(I)), decided exactly, stored as k/255.
uniform float shadelabHalfSteps[255]; // the least float at or above (k - 0.5)/255, k = 1..255
float shadelabQuantised(float v)
{
  float c = clamp(v, 0.0, 1.0);
  int k = int(c * 255.0 + 0.5); // k or k + 1 (IEEE rounding is monotonic, half steps are floats)
  if (k > 0 && c < shadelabHalfSteps[k - 1])
  {
    k -= 1;
  }
  return float(k) / 255.0;
}
vec4 shadelabQuantised(vec4 v)
{
  return vec4(shadelabQuantised(v.r), shadelabQuantised(v.g), shadelabQuantised(v.b),
    shadelabQuantised(v.a));
}
out vec4 fragOutput0;


// Apple Bug
//VTK::PrimID::Dec

// handle coincident offsets
//VTK::Coincident::Dec

// Value raster
//VTK::ValuePass::Dec

// surface with edges
//VTK::Edges::Dec

void main()
{
  // VC position of this fragment. This should not branch/return/discard.
  vec4 vertexVC = vertexVCVSOutput;

  // Place any calls that require uniform flow (e.g. dFdx) here.
  

  // Set gl_FragDepth here (gl_FragCoord.z by default)
  //VTK::Depth::Impl

  // Early depth peeling abort:
  //VTK::DepthPeeling::PreColor

  // Apple Bug
  //VTK::PrimID::Impl

  //VTK::Clip::Impl

  //VTK::ValuePass::Impl

    vec3 specularColor = specularIntensity * specularColorUniform;
  float specularPower = specularPowerUniform;
  vec3 ambientColor = ambientIntensity * ambientColorUniform;
  vec3 diffuseColor = diffuseIntensity * diffuseColorUniform;
  float opacity = opacityUniform;


  //VTK::Edges::Impl

  // Generate the normal if we are not passed in one
  

    fragOutput0 = vec4(shadelabKd, 1.0);


  //VTK::TCoord::Impl

  if (fragOutput0.a <= 0.0)
    {
    discard;
    }

  //VTK::DepthPeeling::Impl

  //VTK::Picking::Impl

  // handle coincident offsets
  //VTK::Coincident::Impl
  fragOutput0 = shadelabQuantised(fragOutput0);

}
