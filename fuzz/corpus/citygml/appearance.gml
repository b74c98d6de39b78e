<?xml version="1.0" encoding="UTF-8"?>
<core:CityModel xmlns:core="http://www.opengis.net/citygml/2.0" xmlns:bldg="http://www.opengis.net/citygml/building/2.0"
  xmlns:gml="http://www.opengis.net/gml" xmlns:app="http://www.opengis.net/citygml/appearance/2.0">
<core:cityObjectMember><bldg:Building gml:id="b1"><bldg:boundedBy><bldg:RoofSurface><bldg:lod2MultiSurface>
<gml:MultiSurface srsName="http://www.opengis.net/def/crs/EPSG/0/6697" srsDimension="3">
<gml:surfaceMember><gml:Polygon gml:id="p1"><gml:exterior><gml:LinearRing gml:id="r1"><gml:posList>
35.5 139.7 10 35.5 139.70011 10 35.50009 139.70011 10 35.50009 139.7 10 35.5 139.7 10
</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
<gml:surfaceMember><gml:Polygon gml:id="p2"><gml:exterior><gml:LinearRing gml:id="r2"><gml:posList>
35.5 139.70022 10 35.5 139.70033 10 35.50009 139.70033 10 35.50009 139.70022 10 35.5 139.70022 10
</gml:posList></gml:LinearRing></gml:exterior></gml:Polygon></gml:surfaceMember>
</gml:MultiSurface></bldg:lod2MultiSurface></bldg:RoofSurface></bldg:boundedBy></bldg:Building></core:cityObjectMember>
<app:appearanceMember><app:Appearance><app:theme>rgbTexture</app:theme>
<app:surfaceDataMember><app:ParameterizedTexture><app:imageURI>tex/roof.png</app:imageURI>
<app:target uri="#p1"><app:TexCoordList>
<app:textureCoordinates ring="#r1">0 0 1 0 1 1 0 1 0 0</app:textureCoordinates>
</app:TexCoordList></app:target></app:ParameterizedTexture></app:surfaceDataMember>
<app:surfaceDataMember><app:X3DMaterial gml:id="tile"><app:diffuseColor>0.2 0.3 0.5</app:diffuseColor>
<app:specularColor>0.04 0.04 0.04</app:specularColor><app:shininess>0.5</app:shininess>
<app:target>#p2</app:target></app:X3DMaterial></app:surfaceDataMember>
</app:Appearance></app:appearanceMember>
</core:CityModel>
