#version 150
#ifndef GL_ES
#define highp
#define mediump
#define lowp
#endif // GL_ES
#define attribute in
#define varying out


/*=========================================================================

  Program:   Visualization Toolkit
  Module:    vtkPolyDataVS.glsl

  Copyright (c) Ken Martin, Will Schroeder, Bill Lorensen
  All rights reserved.
  See Copyright.txt or http://www.kitware.com/Copyright.htm for details.

     This software is distributed WITHOUT ANY WARRANTY; without even
     the implied warranty of MERCHANTABILITY or FITNESS FOR A PARTICULAR
     PURPOSE.  See the above copyright notice for more information.

=========================================================================*/

in vec4 vertexMC;



// frag position in VC
out vec4 vertexVCVSOutput;

// optional normal declaration
//VTK::Normal::Dec

// extra lighting parameters
flat out vec4 shadelabProvokingVC;


// Texture coordinates
//VTK::TCoord::Dec

// material property values
//VTK::Color::Dec

// clipping plane vars
//VTK::Clip::Dec

// camera and actor matrix values
uniform mat4 MCDCMatrix;
uniform mat4 MCVCMatrix;

// Apple Bug
//VTK::PrimID::Dec

// Value raster
//VTK::ValuePass::Dec

// picking support
//VTK::Picking::Dec

void main()
{
  //VTK::CustomBegin::Impl

  //VTK::Color::Impl

  //VTK::Normal::Impl

  //VTK::TCoord::Impl

  //VTK::Clip::Impl

  //VTK::PrimID::Impl

  vertexVCVSOutput = MCVCMatrix * vertexMC;
  gl_Position = MCDCMatrix * vertexMC;


  //VTK::ValuePass::Impl

    shadelabProvokingVC = vertexVCVSOutput;


  //VTK::Picking::Impl

  //VTK::CustomEnd::Impl
}
